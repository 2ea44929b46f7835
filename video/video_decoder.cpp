#include "video_decoder.h"

#include "frame_index_store.h"
#include "frame_reader.h"
#include "video_error.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <opencv2/imgproc.hpp>

namespace nb::video {

QImage toQImage(const cv::Mat& bgr)
{
    if (bgr.empty())
        return {};
    cv::Mat rgb;
    if (bgr.channels() == 1)
        cv::cvtColor(bgr, rgb, cv::COLOR_GRAY2RGB);
    else
        cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return QImage(rgb.data, rgb.cols, rgb.rows, int(rgb.step), QImage::Format_RGB888).copy();
}

class DecoderWorker : public QObject {
    Q_OBJECT
public:
    std::atomic_int pending{-1};
    std::atomic_bool serveQueued{false};
    std::atomic_int back{10}, ahead{15};

    void open(const QString& path, std::shared_ptr<std::atomic_bool> cancel)
    {
        reader_.reset();
        path_ = path;
        try {
            FrameIndex index = loadOrBuildFrameIndex(
                path, [this, path](int done, int expected) { emit indexProgress(path, done, expected); }, cancel.get());
            if (cancel->load())
                return;
            auto shared = std::make_shared<const FrameIndex>(index);
            reader_ = std::make_unique<FrameReader>(std::move(index), 96);
            emit opened(path, shared);
        } catch (const VideoError& e) {
            // An index stopped because another open was asked is no failure of the file, and the
            // file asked for next may be this same one (the run's own video attached again while
            // it was still indexed): "no frame could be decoded" undid that attach.
            if (!cancel->load())
                emit failed(path, e.message());
        }
    }

    void close()
    {
        reader_.reset();
        path_.clear();
        cursor_ = -1;
        pending = -1;
    }

    void serve()
    {
        serveQueued = false;
        const int n = pending.exchange(-1);
        if (!reader_ || n < 0)
            return;
        try {
            const DecodedFrame f = reader_->read(n);
            cursor_ = n;
            emit frameReady(path_, f.index, f.time_s, toQImage(f.image));
        } catch (const VideoError& e) {
            emit failed(path_, e.message());
            return;
        }
        scheduleFill();
    }

    void fill()
    {
        fillQueued_ = false;
        if (!reader_ || cursor_ < 0 || pending.load() >= 0)
            return;  // a new request wins over the prefetch
        try {
            // A few frames at a time, so a request waits at most that long.
            const int done = reader_->fillCache(cursor_ - back, cursor_ + ahead, 4);
            if (done > 0)
                scheduleFill();
        } catch (const VideoError&) {
            // The request path reports unreadable frames; prefetch just stops.
        }
    }

signals:
    // Each names the file it is about: what the window hears is only the file it opened last.
    void indexProgress(const QString& path, int done, int expected);
    void opened(const QString& path, nb::video::FrameIndexPtr index);
    void failed(const QString& path, const QString& message);
    void frameReady(const QString& path, int index, double time_s, const QImage& image);

private:
    void scheduleFill()
    {
        if (fillQueued_)
            return;
        fillQueued_ = true;
        QMetaObject::invokeMethod(this, &DecoderWorker::fill, Qt::QueuedConnection);
    }
    std::unique_ptr<FrameReader> reader_;
    QString path_;  // of reader_
    int cursor_ = -1;
    bool fillQueued_ = false;
};

VideoDecoder::VideoDecoder(QObject* parent) : QObject(parent), cancel_(std::make_shared<std::atomic_bool>(false))
{
    qRegisterMetaType<FrameIndexPtr>();
    worker_ = new DecoderWorker;
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    // A file opened before the last one may still report (its index was built, or a frame of it
    // decoded, before open() was asked again): the run in review showed another run's video
    // and its needle trace, or "no frame could be decoded" of a file no longer shown.
    connect(worker_, &DecoderWorker::indexProgress, this, [this](const QString& path, int done, int expected) {
        if (path == path_)
            emit indexProgress(done, expected);
    });
    connect(worker_, &DecoderWorker::opened, this, [this](const QString& path, FrameIndexPtr index) {
        if (path != path_)
            return;
        index_ = index;
        emit opened(index);
    });
    connect(worker_, &DecoderWorker::failed, this, [this](const QString& path, const QString& message) {
        if (path == path_)
            emit failed(message);
    });
    connect(worker_, &DecoderWorker::frameReady, this, [this](const QString& path, int n, double t, const QImage& image) {
        if (path == path_)
            emit frameReady(n, t, image);
    });
    thread_.setObjectName(QStringLiteral("video decoder"));
    thread_.start();
}

VideoDecoder::~VideoDecoder()
{
    cancel_->store(true);
    thread_.quit();
    thread_.wait();
}

void VideoDecoder::forgetCurrent()
{
    cancel_->store(true);  // an index still being built for the previous file stops
    cancel_ = std::make_shared<std::atomic_bool>(false);
    index_.reset();
    path_.clear();
}

void VideoDecoder::open(const QString& path)
{
    forgetCurrent();
    path_ = path;
    QMetaObject::invokeMethod(worker_, [w = worker_, path, c = cancel_] { w->open(path, c); }, Qt::QueuedConnection);
}

void VideoDecoder::close()
{
    forgetCurrent();
    QMetaObject::invokeMethod(worker_, &DecoderWorker::close, Qt::QueuedConnection);
}

void VideoDecoder::requestFrame(int n)
{
    worker_->pending = n;
    if (!worker_->serveQueued.exchange(true))
        QMetaObject::invokeMethod(worker_, &DecoderWorker::serve, Qt::QueuedConnection);
}

void VideoDecoder::setPrefetch(int back, int ahead)
{
    worker_->back = back;
    worker_->ahead = ahead;
}

}  // namespace nb::video

#include "video_decoder.moc"
