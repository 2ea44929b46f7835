#include "recorder.h"
#include "core/tr.h"

#include "core/disk_space.h"
#include "core/run_file.h"

#include <QCoreApplication>
#include <QFileInfo>
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
    std::chrono::steady_clock::time_point started, nextSpaceCheck;
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

QString Recorder::spaceWarning() const
{
    std::lock_guard lock(mutex_);
    return spaceWarning_;
}

void Recorder::open(const QString& path, const Metadata& metadata, bool truthColumns)
{
    if (running_.load())
        throw RunFileError(path, 0, nb::TrDevices::tr("a run is already being recorded"));
    QStringList columns{QStringLiteral("time_s"),   QStringLiteral("position_mm"), QStringLiteral("force_N"),
                        QStringLiteral("velocity_mm_s"), QStringLiteral("voltage_V"), QStringLiteral("seq")};
    QStringList text;
    if (truthColumns) {
        columns << QStringLiteral("tissue_position_mm");
        text << QStringLiteral("phase");
    }
    const QFileInfo target(path);
    const bool onDisk = !target.exists() || target.isFile();  // not /dev/null or a pipe
    if (const auto free = onDisk ? freeBytes(path) : std::nullopt; free && *free < kMinFreeBytesToRecord)
        throw RunFileError(path, 0, nb::TrDevices::tr("only %1 kB free on the disk; a recording needs at least %2 kB")
                                        .arg(*free / 1024)
                                        .arg(kMinFreeBytesToRecord / 1024));
    impl_->writer.open(path, metadata, columns, text);  // throws before anything starts
    impl_->truth = truthColumns;
    // Drain anything left from a previous run (the ring is reused).
    std::vector<Sample> stale;
    ring_.popAll(stale);
    {
        std::lock_guard lock(mutex_);
        path_ = path;
        error_.clear();
        spaceWarning_.clear();
    }
    failed_ = false;
    spaceWarningPending_ = false;
    spaceLeft_s_ = std::numeric_limits<double>::infinity();
    impl_->started = std::chrono::steady_clock::now();
    impl_->nextSpaceCheck = impl_->started + std::chrono::seconds(1);
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
        if (failed_.load(std::memory_order_relaxed)) {
            // The file keeps what it had; the engine ends the run. Keep draining the ring so
            // that the failure is not also reported as lost samples.
            if (last)
                break;
            std::this_thread::sleep_for(std::chrono::milliseconds(kFlushPeriod_ms));
            continue;
        }
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
            watchSpace();
        } catch (const std::exception& e) {
            {
                std::lock_guard lock(mutex_);
                if (error_.isEmpty())
                    error_ = QString::fromStdString(e.what());
            }
            // Rows on disk are whole; what counts as written is what a reader will find.
            written_ = static_cast<std::uint64_t>(impl_->writer.rowsOnDisk());
            failed_.store(true, std::memory_order_release);
        }
        if (last)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(kFlushPeriod_ms));
    }
    tid_ = 0;
}

void Recorder::watchSpace()
{
    const auto now = std::chrono::steady_clock::now();
    if (now < impl_->nextSpaceCheck)
        return;
    impl_->nextSpaceCheck = now + std::chrono::seconds(1);
    const auto free = freeBytes(impl_->writer.path());
    const double elapsed_s = std::chrono::duration<double>(now - impl_->started).count();
    if (!free || elapsed_s <= 0.0)
        return;
    // The average since the start: steady enough not to raise a warning on one slow flush.
    const double rate = static_cast<double>(impl_->writer.bytesOnDisk()) / elapsed_s;
    const double left_s = secondsUntilFull(*free, rate);
    spaceLeft_s_ = left_s;
    if (left_s < kLowSpaceWarning_s) {
        std::lock_guard lock(mutex_);
        if (spaceWarning_.isEmpty()) {
            spaceWarningPending_ = true;
            spaceWarning_ = nb::TrDevices::tr("the disk holding %1 will be full in about %2 s (%3 kB free)")
                                .arg(impl_->writer.path())
                                .arg(std::max(0.0, left_s), 0, 'f', 0)
                                .arg(*free / 1024);
        }
    }
}

QString Recorder::takeSpaceWarning()
{
    if (!spaceWarningPending_.exchange(false))
        return {};
    return spaceWarning();
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
    if (!err.isEmpty()) {
        // However the run was meant to end, it ended by the failed write.
        if (f.value(QStringLiteral("end_reason"), QString()) != QLatin1String("write_error")) {
            if (f.contains(QStringLiteral("end_reason")))
                f.set(QStringLiteral("end_reason_requested"), f.value(QStringLiteral("end_reason"), QString()));
            f.set(QStringLiteral("end_reason"), QStringLiteral("write_error"));
        }
        f.set(QStringLiteral("write_error"), err);
        f.set(QStringLiteral("rows_written"), static_cast<double>(impl_->writer.rowsOnDisk()));
    }
    try {
        impl_->writer.close(f);
    } catch (const RunFileError& e) {
        // Even the footer did not fit: the file keeps its whole rows and no footer.
        std::lock_guard lock(mutex_);
        if (error_.isEmpty())
            error_ = e.message();
        failed_ = true;
    }
    if (failed_.load())
        written_ = static_cast<std::uint64_t>(impl_->writer.rowsOnDisk());
}

}  // namespace nb::devices
