// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace oi {

using Bytes = std::vector<std::uint8_t>;

// Why an argument, a text or a byte sequence was refused. `field` and the
// range are empty/unset where they do not apply (a parse error, say).
struct OiError {
    std::string field;
    std::optional<long long> value;
    std::optional<long long> min;
    std::optional<long long> max;
    std::string message;

    // One line for a person: "velocity: -600 is outside -500..500".
    std::string describe() const;

    static OiError outOfRange(std::string field, long long value, long long min, long long max);
    static OiError invalid(std::string field, std::string message);
};

// A value or the reason there is none. `warning` carries advice that does not
// stop the command (e.g. "slot 4 may not play on some firmware").
template <typename T>
class Result {
public:
    Result(T value) : m_value(std::move(value)) {}
    Result(OiError error) : m_error(std::move(error)) {}

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }

    const T &value() const & { return *m_value; }
    T &&value() && { return std::move(*m_value); }
    const T &operator*() const { return *m_value; }
    const T *operator->() const { return &*m_value; }
    const OiError &error() const { return m_error; }

    std::string warning;

private:
    std::optional<T> m_value;
    OiError m_error;
};

using EncodeResult = Result<Bytes>;

} // namespace oi
