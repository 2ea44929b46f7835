#include "recorder.h"

#include "core/run_file.h"

#include <QCoreApplication>
#include <array>
#include <chrono>
#include <cmath>
#include <unistd.h>
#include <sys/syscall.h>
#include <vector>

namespace nb::devices {

namespace {
constexpr std::size_t kRingCapacity = 1 << 18;  // 26 s at 10 kHz: rides out slow disks
}

struct Recorder::Impl {
    RunFileWriter writer;
    bool truth = false;
};

Recorder::Recorder() : ring_(kRingCapacity), impl_(std::make_unique<Impl>()) {}

Recorder::~Recorder()
{
    if (running_.load()) {
        Metadata footer;
        footer.set(QStringLiteral("end_reason"), QStringLiteral("aborted"));
        try {
            close(footer);
        } catch (...) {
        }
    }
}

QString Recorder::path() const
{
    std::lock_guard lock(mutex_);
    return path_;
}

QString Recorder::error() const
{
    std::lock_guard lock(mutex_);
    return error_;
}

void Recorder::open(const QString& path, const Metadata& metadata, bool truthColumns)
{
    if (running_.load())
        throw RunFileError(path, 0, QCoreApplication::translate("nb::devices::Recorder", "a run is already being recorded"));
    QStringList columns{QStringLiteral("time_s"),   QStringLiteral("position_mm"), QStringLiteral("force_N"),
                        QStringLiteral("velocity_mm_s"), QStringLiteral("voltage_V"), QStringLiteral("seq")};
    QStringList text;
    if (truthColumns) {
        columns << QStringLiteral("tissue_position_mm");
        text << QStringLiteral("phase");
    }
    impl_->writer.open(path, metadata, columns, text);  // throws before anything starts
    impl_->truth = truthColumns;
    // Drain anything left from a previous run (the ring is reused).
    std::vector<Sample> stale;
    ring_.popAll(stale);
    {
        std::lock_guard lock(mutex_);
        path_ = path;
        error_.clear();
    }
    written_ = 0;
    stopRequested_ = false;
    running_ = true;
    thread_ = std::thread([this] { writerLoop(); });
}

void Recorder::writerLoop()
{
    tid_ = static_cast<int>(::syscall(SYS_gettid));
    std::vector<Sample> batch;
    batch.reserve(4096);
    for (;;) {
        const bool last = stopRequested_.load(std::memory_order_acquire);
        batch.clear();
        ring_.popAll(batch);
        try {
            for (const Sample& s : batch) {
                if (impl_->truth) {
                    const std::array<double, 7> row{s.time_s, s.position_mm, s.force_N, s.velocity_mm_s,
                                                    s.volts, static_cast<double>(s.seq), s.tissue_position_mm};
                    const QString& ph = phaseName(s.phase);
                    impl_->writer.writeRow(row, std::span<const QString>(&ph, 1));
                } else {
                    const std::array<double, 6> row{s.time_s, s.position_mm, s.force_N, s.velocity_mm_s,
                                                    s.volts, static_cast<double>(s.seq)};
                    impl_->writer.writeRow(row);
                }
            }
            // Unbuffered file: after flush() the rows are in the kernel and survive kill -9.
            impl_->writer.flush();
            written_.fetch_add(batch.size());
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            if (error_.isEmpty())
                error_ = QString::fromStdString(e.what());
        }
        if (last)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(kFlushPeriod_ms));
    }
    tid_ = 0;
}

void Recorder::close(const Metadata& footer)
{
    if (!running_.load())
        return;
    stopRequested_.store(true, std::memory_order_release);
    thread_.join();
    running_ = false;
    Metadata f = footer;
    const QString err = error();
    if (!err.isEmpty())
        f.set(QStringLiteral("write_error"), err);
    impl_->writer.close(f);
}

}  // namespace nb::devices
