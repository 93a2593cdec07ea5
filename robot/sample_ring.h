// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

// A ring buffer that allocates as it fills: it starts small and doubles up
// to the capacity it is given, so a short session holds little memory and
// a long one never more than capacity elements. Once full, a push drops
// the oldest element.
template <typename T>
class SampleRing {
public:
    using value_type = T;
    static constexpr std::size_t kFirstBlock = 1024;

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    std::size_t bytes() const { return m_buffer.capacity() * sizeof(T); }

    // Element `index`, 0 being the oldest.
    const T &operator[](std::size_t index) const { return m_buffer[physical(index)]; }
    const T &front() const { return m_buffer[m_head]; }
    const T &back() const { return (*this)[m_size - 1]; }

    void push(T value, std::size_t capacity)
    {
        if (m_size == m_buffer.size() && m_size < capacity)
            grow(std::min(capacity, std::max(kFirstBlock, m_size * 2)));
        if (m_size < m_buffer.size()) {
            m_buffer[physical(m_size)] = value;
            ++m_size;
        } else { // full at the capacity
            m_buffer[m_head] = value;
            m_head = m_head + 1 == m_buffer.size() ? 0 : m_head + 1;
        }
    }

    void popFront()
    {
        m_head = m_head + 1 == m_buffer.size() ? 0 : m_head + 1;
        --m_size;
    }

    // Gives the memory back, not just the elements.
    void release() { *this = SampleRing{}; }

    // The same elements in another type (for widening), oldest first.
    template <typename U>
    SampleRing<U> convertedTo(std::size_t capacity) const
    {
        SampleRing<U> out;
        out.grow(std::max(m_buffer.size(), std::min(capacity, kFirstBlock)));
        for (std::size_t i = 0; i < m_size; ++i)
            out.push(U((*this)[i]), capacity);
        return out;
    }

private:
    template <typename U>
    friend class SampleRing;

    std::size_t physical(std::size_t index) const
    {
        const std::size_t p = m_head + index;
        return p >= m_buffer.size() ? p - m_buffer.size() : p;
    }

    void grow(std::size_t allocation)
    {
        // Allocated exactly, so bytes() is what the ring holds.
        std::vector<T> bigger(allocation);
        for (std::size_t i = 0; i < m_size; ++i)
            bigger[i] = (*this)[i];
        m_buffer = std::move(bigger);
        m_head = 0;
    }

    std::vector<T> m_buffer; // its size is the ring's allocation
    std::size_t m_head = 0;  // physical index of the oldest element
    std::size_t m_size = 0;
};
