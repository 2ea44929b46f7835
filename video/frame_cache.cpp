#include "frame_cache.h"

#include <algorithm>

namespace nb::video {

void FrameCache::setCapacity(int frames)
{
    capacity_ = std::max(1, frames);
    evict();
}

std::optional<cv::Mat> FrameCache::get(int index)
{
    auto it = map_.find(index);
    if (it == map_.end())
        return std::nullopt;
    order_.splice(order_.begin(), order_, it->second.second);
    return it->second.first;
}

void FrameCache::put(int index, const cv::Mat& image)
{
    auto it = map_.find(index);
    if (it != map_.end()) {
        it->second.first = image;
        order_.splice(order_.begin(), order_, it->second.second);
        return;
    }
    order_.push_front(index);
    map_.emplace(index, std::make_pair(image, order_.begin()));
    evict();
}

void FrameCache::clear()
{
    map_.clear();
    order_.clear();
}

void FrameCache::evict()
{
    while (int(map_.size()) > capacity_) {
        map_.erase(order_.back());
        order_.pop_back();
    }
}

}  // namespace nb::video
