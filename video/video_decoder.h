#pragma once
// Decoding off the GUI thread: a worker thread indexes the file (with progress), then serves
// frame requests, newest first (a scrub that outruns the decoder skips the stale requests),
// and, when idle, fills the cache around the cursor so stepping back is instant.
// All signals arrive queued in the thread that owns the VideoDecoder.

#include "frame_index.h"

#include <QImage>
#include <QObject>
#include <QThread>

#include <atomic>
#include <memory>

namespace cv {
class Mat;
}

namespace nb::video {

using FrameIndexPtr = std::shared_ptr<const FrameIndex>;

class DecoderWorker;

class VideoDecoder : public QObject {
    Q_OBJECT
public:
    explicit VideoDecoder(QObject* parent = nullptr);
    ~VideoDecoder() override;

    // Starts indexing `path`; ends in opened() or failed().
    void open(const QString& path);
    // Lets the file opened last go: its indexing stops, and nothing more is said of it.
    void close();
    // Asks for frame n; only the newest pending request is served.
    void requestFrame(int n);
    FrameIndexPtr index() const { return index_; }
    // Frames around the cursor that the idle worker keeps decoded (each way).
    void setPrefetch(int back, int ahead);

signals:
    void indexProgress(int done, int expected);
    void opened(nb::video::FrameIndexPtr index);
    void failed(const QString& message);
    void frameReady(int index, double time_s, const QImage& image);

private:
    void forgetCurrent();  // the file opened last: its indexing stopped, its answers no longer heard
    QThread thread_;
    DecoderWorker* worker_ = nullptr;
    FrameIndexPtr index_;
    QString path_;  // the file opened last
    std::shared_ptr<std::atomic_bool> cancel_;
};

// QImage (RGB) copy of a BGR OpenCV frame.
QImage toQImage(const cv::Mat& bgr);

}  // namespace nb::video

Q_DECLARE_METATYPE(nb::video::FrameIndexPtr)
