#include "session_hdf5.h"
#include "core/tr.h"

#include "label_intervals.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QScopeGuard>
#include <filesystem>
#include <hdf5.h>
#include <system_error>

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

    Handle stringType() const
    {
        Handle t(checked(H5Tcopy(H5T_C_S1), QStringLiteral("create a string type")), H5Tclose);
        check(H5Tset_size(t, H5T_VARIABLE) >= 0 && H5Tset_cset(t, H5T_CSET_UTF8) >= 0, QStringLiteral("set up a string type"));
        return Handle(H5Tcopy(t), H5Tclose);
    }

    void attribute(hid_t obj, const QString& name, const QString& value) const
    {
        const Handle type = stringType();
        const Handle space(checked(H5Screate(H5S_SCALAR), name), H5Sclose);
        const QByteArray n = name.toUtf8();
        if (H5Aexists(obj, n.constData()) > 0)
            H5Adelete(obj, n.constData());
        const Handle attr(checked(H5Acreate2(obj, n.constData(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                                  nb::TrCore::tr("create attribute '%1'").arg(name)),
                          H5Aclose);
        const QByteArray v = value.toUtf8();
        const char* p = v.constData();
        check(H5Awrite(attr, type, &p) >= 0, nb::TrCore::tr("write attribute '%1'").arg(name));
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

    // A metadata field as a number when it reads as one, plus its unit.
    void metadataAttribute(hid_t obj, const QString& key, const QString& value) const
    {
        bool ok = false;
        const double d = value.trimmed().toDouble(&ok);
        if (ok)
            attribute(obj, key, d);
        else
            attribute(obj, key, value);
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

    void integers(hid_t group, const QString& name, const std::vector<long long>& values) const
    {
        const Handle d = dataset(group, name, H5T_STD_I64LE, values.size());
        if (!values.empty())
            check(H5Dwrite(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0,
                  nb::TrCore::tr("write dataset '%1'").arg(name));
    }

    void strings(hid_t group, const QString& name, const QStringList& values) const
    {
        const Handle type = stringType();
        const Handle d = dataset(group, name, type, std::size_t(values.size()));
        std::vector<QByteArray> bytes;
        std::vector<const char*> ptrs;
        bytes.reserve(std::size_t(values.size()));
        for (const QString& v : values)
            bytes.push_back(v.toUtf8());
        for (const QByteArray& b : bytes)
            ptrs.push_back(b.constData());
        if (!ptrs.empty())
            check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) >= 0, nb::TrCore::tr("write dataset '%1'").arg(name));
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
        if (!r.sourcePath.isEmpty())
            attribute(g, QStringLiteral("source"), r.sourcePath);
        attribute(g, QStringLiteral("samples"), double(r.run.size()));
        for (const Metadata* m : {&r.run.metadata, &r.run.footer})  // the footer is written last and wins
            for (const auto& [key, value] : m->entries())
                metadataAttribute(g, key, value);
        attribute(g, QStringLiteral("sync_offset_s"), syncOffset(r.run));
        attribute(g, QStringLiteral("sync_offset_s_units"), QStringLiteral("s"));
        attribute(g, QStringLiteral("video_fps"), videoFps(r.run));

        for (const SignalColumn& c : exportSignals(r.run))
            doubles(g, c.name, c.values, c.unit, c.description);

        const auto rows = labelIntervals(r.run, r.labels, frameClockFor(r.run));
        const Handle lg = group(g, QStringLiteral("labels"));
        attribute(lg, QStringLiteral("description"),
                  nb::TrCore::tr("one row per label; frames from the sync offset and frame rate of the run"));
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
        integers(lg, QStringLiteral("start_frame"), f0);
        integers(lg, QStringLiteral("end_frame"), f1);
        doubles(lg, QStringLiteral("peak_force_N"), peak, QStringLiteral("N"), nb::TrCore::tr("NaN when no sample lies in the interval"));
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

bool writeSessionHdf5(const QString& path, const Dataset& dataset, const ExportProgress& progress)
{
    // HDF5 prints its own error stack to stderr by default; the ExportError says it better.
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const QString temp = path + QStringLiteral(".part");
    const QByteArray tempName = QFile::encodeName(temp);
    bool done = false;
    {
        const Writer w(path);
        const Handle file(H5Fcreate(tempName.constData(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        if (!file.valid())
            throw ExportError(path, nb::TrCore::tr("cannot create the file (is the folder writable?)"));
        auto cleanup = qScopeGuard([&] {
            if (!done)
                QFile::remove(temp);
        });
        w.attribute(file, QStringLiteral("format"), QStringLiteral("needlebench-session"));
        w.attribute(file, QStringLiteral("version"), 1.0);
        w.attribute(file, QStringLiteral("session"), dataset.name);
        w.attribute(file, QStringLiteral("created"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
        for (const auto& [key, value] : dataset.metadata.entries())
            w.metadataAttribute(file, key, value);
        const Handle runs = w.group(file, QStringLiteral("runs"));
        const qint64 total = qint64(dataset.runs.size());
        if (!keepGoing(progress, 0, total))
            return false;
        for (std::size_t i = 0; i < dataset.runs.size(); ++i) {
            w.run(runs, dataset.runs[i]);
            if (!keepGoing(progress, qint64(i + 1), total))
                return false;
        }
        w.check(H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0, nb::TrCore::tr("flush the file"));
        done = true;
        cleanup.dismiss();
    }
    std::error_code ec;
    std::filesystem::rename(std::filesystem::path(tempName.toStdString()), std::filesystem::path(QFile::encodeName(path).toStdString()), ec);
    if (ec) {
        QFile::remove(temp);
        throw ExportError(path, nb::TrCore::tr("cannot rename the finished file into place: %1").arg(QString::fromStdString(ec.message())));
    }
    return true;
}

}  // namespace nb
