#include "session_hdf5.h"
#include "core/tr.h"

#include "label_intervals.h"
#include "stale_parts.h"

#include "core/models.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QScopeGuard>
#include <cmath>
#include <cstring>
#include <cerrno>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <hdf5.h>

namespace nb {

namespace {

// Owns one HDF5 identifier and closes it with the matching H5*close.
class Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Handle(hid_t id, Closer close) : id_(id), close_(close) {}
    ~Handle()
    {
        if (id_ >= 0)
            close_(id_);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    operator hid_t() const { return id_; }
    bool valid() const { return id_ >= 0; }

private:
    hid_t id_;
    Closer close_;
};

class Writer {
public:
    explicit Writer(QString path) : path_(std::move(path)) {}

    void check(bool ok, const QString& what) const
    {
        if (!ok)
            throw ExportError(path_, nb::TrCore::tr("HDF5 could not %1").arg(what));
    }

    hid_t checked(hid_t id, const QString& what) const
    {
        check(id >= 0, what);
        return id;
    }

    // Fixed-length strings padded with NULs: Octave's load and MATLAB's h5read read them.
    // Octave converts neither variable-length strings nor ones marked UTF-8 (no conversion
    // path to its ASCII type), so all text is marked ASCII: plain ASCII is exactly that, and
    // other text keeps its UTF-8 bytes (h5py: .decode('utf-8'); MATLAB: native2unicode).
    Handle stringType(std::size_t bytes) const
    {
        Handle t(checked(H5Tcopy(H5T_C_S1), QStringLiteral("create a string type")), H5Tclose);
        check(H5Tset_size(t, std::max<std::size_t>(bytes, 1)) >= 0 && H5Tset_strpad(t, H5T_STR_NULLPAD) >= 0 &&
                  H5Tset_cset(t, H5T_CSET_ASCII) >= 0,
              QStringLiteral("set up a string type"));
        return Handle(H5Tcopy(t), H5Tclose);
    }

    void attribute(hid_t obj, const QString& name, const QString& value) const
    {
        QByteArray v = value.toUtf8();
        const Handle type = stringType(std::size_t(v.size()));
        const Handle space(checked(H5Screate(H5S_SCALAR), name), H5Sclose);
        const QByteArray n = name.toUtf8();
        if (H5Aexists(obj, n.constData()) > 0)
            H5Adelete(obj, n.constData());
        const Handle attr(checked(H5Acreate2(obj, n.constData(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                                  nb::TrCore::tr("create attribute '%1'").arg(name)),
                          H5Aclose);
        if (v.isEmpty())
            v = QByteArray(1, '\0');
        check(H5Awrite(attr, type, v.constData()) >= 0, nb::TrCore::tr("write attribute '%1'").arg(name));
    }

    void attribute(hid_t obj, const QString& name, double value) const
    {
        const Handle space(checked(H5Screate(H5S_SCALAR), name), H5Sclose);
        const QByteArray n = name.toUtf8();
        if (H5Aexists(obj, n.constData()) > 0)
            H5Adelete(obj, n.constData());
        const Handle attr(checked(H5Acreate2(obj, n.constData(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT),
                                  nb::TrCore::tr("create attribute '%1'").arg(name)),
                          H5Aclose);
        check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) >= 0, nb::TrCore::tr("write attribute '%1'").arg(name));
    }

    void attribute(hid_t obj, const QString& name, long long value) const
    {
        const Handle space(checked(H5Screate(H5S_SCALAR), name), H5Sclose);
        const QByteArray n = name.toUtf8();
        if (H5Aexists(obj, n.constData()) > 0)
            H5Adelete(obj, n.constData());
        const Handle attr(checked(H5Acreate2(obj, n.constData(), H5T_STD_I64LE, space, H5P_DEFAULT, H5P_DEFAULT),
                                  nb::TrCore::tr("create attribute '%1'").arg(name)),
                          H5Aclose);
        check(H5Awrite(attr, H5T_NATIVE_LLONG, &value) >= 0, nb::TrCore::tr("write attribute '%1'").arg(name));
    }

    // A metadata field as an integer or a number when it is written as one (not "nan" or
    // "inf": those stay the text they were), plus its unit. Fields that are text by nature
    // (organ, tip, operator...) stay text whatever they hold.
    void metadataAttribute(hid_t obj, const QString& key, const QString& value) const
    {
        switch (metadataValueKind(key, value)) {
        case MetadataValueKind::Integer: attribute(obj, key, value.trimmed().toLongLong()); break;
        case MetadataValueKind::Number: attribute(obj, key, value.trimmed().toDouble()); break;
        case MetadataValueKind::Text: attribute(obj, key, value); break;
        }
        const QString unit = unitFromName(key);
        if (!unit.isEmpty())
            attribute(obj, key + QStringLiteral("_units"), unit);
    }

    Handle dataset(hid_t group, const QString& name, hid_t fileType, std::size_t n) const
    {
        const hsize_t dims[1] = {hsize_t(n)};
        const Handle space(checked(H5Screate_simple(1, dims, nullptr), name), H5Sclose);
        const Handle dcpl(checked(H5Pcreate(H5P_DATASET_CREATE), name), H5Pclose);
        // Compress large signals; chunking needs a non-empty dataset.
        if (n > 1024 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
            const hsize_t chunk[1] = {hsize_t(std::min<std::size_t>(n, 16384))};
            check(H5Pset_chunk(dcpl, 1, chunk) >= 0 && H5Pset_deflate(dcpl, 4) >= 0, nb::TrCore::tr("set up compression for '%1'").arg(name));
        }
        return Handle(checked(H5Dcreate2(group, name.toUtf8().constData(), fileType, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                              nb::TrCore::tr("create dataset '%1'").arg(name)),
                      H5Dclose);
    }

    void doubles(hid_t group, const QString& name, const std::vector<double>& values, const QString& unit,
                 const QString& description) const
    {
        const Handle d = dataset(group, name, H5T_IEEE_F64LE, values.size());
        if (!values.empty())
            check(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
                  nb::TrCore::tr("write dataset '%1'").arg(name));
        attribute(d, QStringLiteral("units"), unit);
        if (!description.isEmpty())
            attribute(d, QStringLiteral("description"), description);
    }

    void integers(hid_t group, const QString& name, const std::vector<long long>& values, const QString& unit,
                  const QString& description = {}) const
    {
        const Handle d = dataset(group, name, H5T_STD_I64LE, values.size());
        if (!values.empty())
            check(H5Dwrite(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
                  nb::TrCore::tr("write dataset '%1'").arg(name));
        attribute(d, QStringLiteral("units"), unit);
        if (!description.isEmpty())
            attribute(d, QStringLiteral("description"), description);
    }

    void strings(hid_t group, const QString& name, const QStringList& values, const QString& description = {}) const
    {
        std::vector<QByteArray> bytes;
        bytes.reserve(std::size_t(values.size()));
        std::size_t width = 1;
        for (const QString& v : values) {
            bytes.push_back(v.toUtf8());
            width = std::max(width, std::size_t(bytes.back().size()));
        }
        const Handle type = stringType(width);
        const Handle d = dataset(group, name, type, bytes.size());
        std::vector<char> buffer(bytes.size() * width, '\0');
        for (std::size_t i = 0; i < bytes.size(); ++i)
            std::memcpy(buffer.data() + i * width, bytes[i].constData(), std::size_t(bytes[i].size()));
        if (!bytes.empty())
            check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) >= 0, nb::TrCore::tr("write dataset '%1'").arg(name));
        // Text has no unit; the attribute is there so that every dataset carries one.
        attribute(d, QStringLiteral("units"), QStringLiteral("none"));
        if (!description.isEmpty())
            attribute(d, QStringLiteral("description"), description);
    }

    Handle group(hid_t parent, const QString& name) const
    {
        return Handle(checked(H5Gcreate2(parent, name.toUtf8().constData(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                              nb::TrCore::tr("create group '%1'").arg(name)),
                      H5Gclose);
    }

    void run(hid_t runs, const DatasetRun& r) const
    {
        const Handle g = group(runs, hdf5GroupName(r.name));
        attribute(g, QStringLiteral("name"), r.name);
        // Links relative to this file, so that the folder can move with its run files.
        if (!r.sourcePath.isEmpty()) {
            attribute(g, QStringLiteral("source"), portableLink(path_, r.sourcePath));
            attribute(g, QStringLiteral("source_absolute"), QFileInfo(r.sourcePath).absoluteFilePath());
        }
        if (!r.videoPath.isEmpty()) {
            attribute(g, QStringLiteral("video"), portableLink(path_, r.videoPath));
            attribute(g, QStringLiteral("video_absolute"), r.videoPath);
        }
        attribute(g, QStringLiteral("samples"), static_cast<long long>(r.run.size()));
        for (const Metadata* m : {&r.run.metadata, &r.run.footer})  // the footer is written last and wins
            for (const auto& [key, value] : m->entries())
                metadataAttribute(g, key, value);
        const FrameClock clock = frameClockFor(r);
        if (clock.hasVideo || namedSyncOffset(r.run)) {
            attribute(g, QStringLiteral("sync_offset_s"), syncOffset(r.run));
            attribute(g, QStringLiteral("sync_offset_s_units"), QStringLiteral("s"));
        }
        if (clock.hasVideo) {
            attribute(g, QStringLiteral("video_fps"), videoFps(r.run));
            attribute(g, QStringLiteral("video_fps_units"), QStringLiteral("1/s"));
        }

        for (const SignalColumn& c : exportSignals(r.run)) {
            if (c.integer) {
                std::vector<long long> v;
                v.reserve(c.values.size());
                for (double x : c.values)
                    v.push_back(std::isfinite(x) ? static_cast<long long>(std::llround(x)) : -1);
                integers(g, c.name, v, c.unit, c.description);
            } else {
                doubles(g, c.name, c.values, c.unit, c.description);
            }
        }

        for (const TextColumn& c : exportTextColumns(r.run, r.labels))
            strings(g, c.name, c.values, c.description);

        const auto rows = labelIntervals(r.run, r.labels, clock);
        const Handle lg = group(g, QStringLiteral("labels"));
        attribute(lg, QStringLiteral("description"),
                  clock.hasVideo ? nb::TrCore::tr("one row per label; frames from the sync offset and frame rate of the run")
                                 : nb::TrCore::tr("one row per label; no frames: the run has no video"));
        QStringList label, track, comment;
        std::vector<double> start, end, duration, peak, mean;
        std::vector<long long> f0, f1;
        for (const LabelInterval& row : rows) {
            label << row.label;
            track << row.track;
            comment << row.comment;
            start.push_back(row.start_s);
            end.push_back(row.end_s);
            duration.push_back(row.duration_s);
            peak.push_back(row.peak_force_N);
            mean.push_back(row.mean_force_N);
            f0.push_back(row.start_frame);
            f1.push_back(row.end_frame);
        }
        strings(lg, QStringLiteral("label"), label);
        strings(lg, QStringLiteral("track"), track);
        doubles(lg, QStringLiteral("start_s"), start, QStringLiteral("s"), {});
        doubles(lg, QStringLiteral("end_s"), end, QStringLiteral("s"), {});
        doubles(lg, QStringLiteral("duration_s"), duration, QStringLiteral("s"), {});
        if (clock.hasVideo) {
            const QString why = nb::TrCore::tr("video frame index (0 = first frame); -1 outside the video");
            integers(lg, QStringLiteral("start_frame"), f0, QStringLiteral("frame"), why);
            integers(lg, QStringLiteral("end_frame"), f1, QStringLiteral("frame"), why);
        }
        doubles(lg, QStringLiteral("peak_force_N"), peak, QStringLiteral("N"),
                nb::TrCore::tr("extreme force in the direction of motion; NaN when no sample lies in the interval"));
        doubles(lg, QStringLiteral("mean_force_N"), mean, QStringLiteral("N"), nb::TrCore::tr("NaN when no sample lies in the interval"));
        strings(lg, QStringLiteral("comment"), comment);
    }

private:
    QString path_;
};

}  // namespace

QString hdf5GroupName(const QString& runName)
{
    QString n = runName;
    n.replace(QLatin1Char('/'), QLatin1Char('_'));
    if (n.isEmpty() || n == QLatin1String("."))
        n = QStringLiteral("run");
    return n;
}

namespace {

// Writes the finished image to NAME.part (locked while written, so that a cleanup elsewhere
// leaves it alone), syncs it and renames it into place; on any failure nothing is left.
void writeImage(const QString& path, const QString& temp, const std::vector<char>& image)
{
    const QByteArray tempName = QFile::encodeName(temp);
    const int fd = ::open(tempName.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) {
        if (errno == EEXIST)
            throw ExportError(path, nb::TrCore::tr("another export is writing %1").arg(temp));
        throw ExportError(path, nb::TrCore::tr("cannot create %1: %2").arg(temp, QString::fromLocal8Bit(std::strerror(errno))));
    }
    ::flock(fd, LOCK_EX | LOCK_NB);
    auto fail = [&](int err) {
        ::unlink(tempName.constData());
        ::close(fd);
        throw ExportError(path, nb::TrCore::tr("cannot write: %1").arg(QString::fromLocal8Bit(std::strerror(err))));
    };
    const char* p = image.data();
    std::size_t left = image.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            fail(n < 0 ? errno : ENOSPC);
        p += n;
        left -= std::size_t(n);
    }
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
        fail(errno);
    if (::rename(tempName.constData(), QFile::encodeName(path).constData()) != 0) {
        const int err = errno;
        ::unlink(tempName.constData());
        ::close(fd);
        throw ExportError(path, nb::TrCore::tr("cannot rename the finished file into place: %1").arg(QString::fromLocal8Bit(std::strerror(err))));
    }
    ::close(fd);
}

}  // namespace

bool writeSessionHdf5(const QString& path, const Dataset& dataset, const ExportProgress& progress)
{
    // HDF5 prints its own error stack to stderr by default; the ExportError says it better.
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const QString temp = path + QStringLiteral(".part");
    // A .part a killed export left behind (no longer locked) goes; a locked one is another
    // export at work on the same file.
    removeStaleParts(QFileInfo(path).absolutePath());
    if (QFileInfo::exists(temp))
        throw ExportError(path, nb::TrCore::tr("another export is writing %1").arg(temp));
    if (!QFileInfo(QFileInfo(path).absolutePath()).isWritable())
        throw ExportError(path, nb::TrCore::tr("cannot create the file (is the folder writable?)"));
    // The file is built in memory and written by us: HDF5 never meets a full disk (on one it
    // leaves a file it cannot close and crashes at exit), and the disk sees one plain write.
    std::vector<char> image;
    {
        const Writer w(path);
        const Handle fapl(w.checked(H5Pcreate(H5P_FILE_ACCESS), QStringLiteral("set up the file")), H5Pclose);
        w.check(H5Pset_fapl_core(fapl, 4 << 20, false) >= 0 && H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) >= 0,
                QStringLiteral("set up the file in memory"));
        const QByteArray memName = QFile::encodeName(temp) + ".mem";
        const Handle file(H5Fcreate(memName.constData(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose);
        if (!file.valid())
            throw ExportError(path, nb::TrCore::tr("cannot create the file in memory"));
        w.attribute(file, QStringLiteral("format"), QStringLiteral("needlebench-session"));
        w.attribute(file, QStringLiteral("version"), 1LL);
        w.attribute(file, QStringLiteral("session"), dataset.name);
        w.attribute(file, QStringLiteral("created"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
        // How force_N came from the load cell, so that it can be rebuilt from voltage_V.
        w.attribute(file, QStringLiteral("standard_gravity_m_s2"), kGravity_m_s2);
        w.attribute(file, QStringLiteral("standard_gravity_m_s2_units"), QStringLiteral("m/s^2"));
        w.attribute(file, QStringLiteral("force_from_voltage"),
                    QStringLiteral("force_N = (voltage_V - bias_V) * standard_gravity_m_s2 / (1000 * slope_V_per_g); "
                                   "bias_V and slope_V_per_g are attributes of each run (the calibration in force "
                                   "while it was recorded)"));
        for (const auto& [key, value] : dataset.metadata.entries())
            w.metadataAttribute(file, key, value);
        {
            const Handle runs = w.group(file, QStringLiteral("runs"));
            const qint64 total = qint64(dataset.runs.size());
            if (!keepGoing(progress, 0, total))
                return false;
            for (std::size_t i = 0; i < dataset.runs.size(); ++i) {
                w.run(runs, dataset.runs[i]);
                if (!keepGoing(progress, qint64(i + 1), total))
                    return false;
            }
        }
        w.check(H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0, nb::TrCore::tr("flush the file"));
        const ssize_t size = H5Fget_file_image(file, nullptr, 0);
        w.check(size > 0, QStringLiteral("get the file image"));
        image.resize(std::size_t(size));
        w.check(H5Fget_file_image(file, image.data(), image.size()) == size, QStringLiteral("get the file image"));
    }
    writeImage(path, temp, image);
    return true;
}

}  // namespace nb
