#pragma once
// Decoded frames around the cursor, least recently used evicted first, so stepping back a
// frame or replaying a few frames needs no decoding.

#include <opencv2/core.hpp>

#include <list>
#include <optional>
#include <unordered_map>

namespace nb::video {

class FrameCache {
public:
    explicit FrameCache(int capacity = 64) : capacity_(capacity) {}
    void setCapacity(int frames);
    int capacity() const { return capacity_; }
    int size() const { return int(map_.size()); }
    bool contains(int index) const { return map_.count(index) > 0; }
    // The image shares its pixels with the cache entry; treat it as read-only.
    std::optional<cv::Mat> get(int index);
    void put(int index, const cv::Mat& image);
    void clear();

private:
    void evict();
    int capacity_;
    std::list<int> order_;  // most recent first
    std::unordered_map<int, std::pair<cv::Mat, std::list<int>::iterator>> map_;
};

}  // namespace nb::video
