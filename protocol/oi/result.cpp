// SPDX-License-Identifier: GPL-3.0-or-later
#include "result.h"

namespace oi {

std::string OiError::describe() const
{
    std::string text = field.empty() ? std::string() : field + ": ";
    if (!message.empty())
        return text + message;
    if (value && min && max)
        return text + std::to_string(*value) + " is outside " + std::to_string(*min) + ".."
               + std::to_string(*max);
    return text + "invalid";
}

OiError OiError::outOfRange(std::string field, long long value, long long min, long long max)
{
    return OiError{std::move(field), value, min, max, {}};
}

OiError OiError::invalid(std::string field, std::string message)
{
    return OiError{std::move(field), std::nullopt, std::nullopt, std::nullopt, std::move(message)};
}

} // namespace oi
