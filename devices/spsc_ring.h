#pragma once
// Lock-free single-producer/single-consumer ring. The producer never blocks and never
// overwrites unread data: when the ring is full the new element is refused and counted,
// so a slow consumer shows up as a number instead of silently corrupting the stream.

#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <vector>

namespace nb::devices {

template <typename T>
class SpscRing {
public:
    // `capacity` is rounded up to a power of two so that indices wrap with a mask.
    explicit SpscRing(std::size_t capacity)
        : buffer_(std::bit_ceil(capacity < 2 ? std::size_t{2} : capacity)), mask_(buffer_.size() - 1)
    {
    }
    SpscRing(const SpscRing&) = delete;
    SpscRing& operator=(const SpscRing&) = delete;

    std::size_t capacity() const { return buffer_.size(); }

    // Producer thread only. False (and one more overrun) when full.
    bool push(const T& value)
    {
        const std::uint64_t head = head_.load(std::memory_order_relaxed);
        if (head - tailCache_ >= buffer_.size()) {
            tailCache_ = tail_.load(std::memory_order_acquire);
            if (head - tailCache_ >= buffer_.size()) {
                overruns_.fetch_add(1, std::memory_order_relaxed);
                return false;
            }
        }
        buffer_[head & mask_] = value;
        head_.store(head + 1, std::memory_order_release);
        return true;
    }

    // Consumer thread only.
    bool pop(T& out)
    {
        const std::uint64_t tail = tail_.load(std::memory_order_relaxed);
        if (tail == headCache_) {
            headCache_ = head_.load(std::memory_order_acquire);
            if (tail == headCache_)
                return false;
        }
        out = buffer_[tail & mask_];
        tail_.store(tail + 1, std::memory_order_release);
        return true;
    }

    // Consumer thread only: appends up to `max` elements to `out`, returns how many.
    std::size_t popAll(std::vector<T>& out, std::size_t max = SIZE_MAX)
    {
        const std::uint64_t tail = tail_.load(std::memory_order_relaxed);
        headCache_ = head_.load(std::memory_order_acquire);
        std::uint64_t n = headCache_ - tail;
        if (n > max)
            n = max;
        for (std::uint64_t i = 0; i < n; ++i)
            out.push_back(buffer_[(tail + i) & mask_]);
        tail_.store(tail + n, std::memory_order_release);
        return static_cast<std::size_t>(n);
    }

    // Approximate from any thread; exact from the consumer when the producer is idle.
    std::size_t size() const
    {
        return static_cast<std::size_t>(head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire));
    }
    // Elements refused because the ring was full (any thread).
    std::uint64_t overruns() const { return overruns_.load(std::memory_order_relaxed); }
    std::uint64_t pushed() const { return head_.load(std::memory_order_relaxed); }

private:
    static constexpr std::size_t kLine = 64;  // keeps producer and consumer indices off each other's cache line
    std::vector<T> buffer_;
    const std::size_t mask_;
    alignas(kLine) std::atomic<std::uint64_t> head_{0};
    std::uint64_t tailCache_ = 0;             // producer's last view of tail_
    alignas(kLine) std::atomic<std::uint64_t> tail_{0};
    std::uint64_t headCache_ = 0;             // consumer's last view of head_
    alignas(kLine) std::atomic<std::uint64_t> overruns_{0};
};

}  // namespace nb::devices
