#include "labels.h"

#include <QDir>
#include <QFileInfo>
#include "core/spreadsheet_separator.h"
#include "core/tr.h"

#include "run_file.h"
#include "save_file.h"

#include <QFile>
#include <algorithm>
#include <cmath>

namespace nb {

namespace {

// Splits one CSV line, honouring "..." quoting with "" as an escaped quote.
QStringList splitCsv(const QString& line)
{
    QStringList out;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == QLatin1Char('"')) {
                if (i + 1 < line.size() && line[i + 1] == QLatin1Char('"')) {
                    field += c;
                    ++i;
                } else {
                    quoted = false;
                }
            } else {
                field += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',')) {
            out << field.trimmed();
            field.clear();
        } else {
            field += c;
        }
    }
    out << field.trimmed();
    return out;
}

QString quoteIfNeeded(QString s)
{
    if (!s.contains(QLatin1Char(',')) && !s.contains(QLatin1Char('"')))
        return s;
    s.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + s + QLatin1Char('"');
}

}  // namespace

LabelsRead readLabels(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw RunFileError(path, 0, nb::TrCore::tr("cannot open: %1").arg(file.errorString()));
    QString text = QString::fromUtf8(file.readAll());
    if (text.startsWith(QChar(0xFEFF)))
        text.remove(0, 1);
    const QStringList lines = text.split(QLatin1Char('\n'));
    LabelsRead read;
    bool haveHeader = false;
    int col[5] = {-1, -1, -1, -1, -1};
    static const char* names[5] = {"track", "label", "start_s", "end_s", "comment"};
    for (int i = 0; i < lines.size(); ++i) {
        QString line = lines[i];
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
        if (line.trimmed().isEmpty() || line.trimmed().startsWith(QLatin1Char('#')))
            continue;
        const QStringList f = splitCsv(line);
        if (!haveHeader) {
            haveHeader = true;
            for (int k = 0; k < 5; ++k)
                col[k] = int(f.indexOf(QLatin1String(names[k])));
            if (const QString problem = otherSeparatorProblem(line, QStringLiteral("track")); !problem.isEmpty())
                throw RunFileError(path, i + 1, problem);
            for (int k = 0; k < 4; ++k)
                if (col[k] < 0)
                    throw RunFileError(path, i + 1, nb::TrCore::tr("header has no '%1' column").arg(QLatin1String(names[k])));
            continue;
        }
        auto field = [&](int k) { return col[k] >= 0 && col[k] < f.size() ? f[col[k]] : QString(); };
        Label l;
        l.track = field(0);
        l.label = field(1);
        bool ok1 = false, ok2 = false;
        l.start_s = field(2).toDouble(&ok1);
        l.end_s = field(3).toDouble(&ok2);
        l.comment = field(4);
        if (!ok1 || !ok2 || !std::isfinite(l.start_s) || !std::isfinite(l.end_s))
            read.skipped.emplace_back(path, i + 1, nb::TrCore::tr("start_s and end_s must be numbers"));
        else if (l.end_s < l.start_s)
            read.skipped.emplace_back(path, i + 1, nb::TrCore::tr("end_s %1 is before start_s %2").arg(l.end_s).arg(l.start_s));
        else if (l.label.isEmpty())
            read.skipped.emplace_back(path, i + 1, nb::TrCore::tr("empty label"));
        else
            read.labels.push_back(std::move(l));
    }
    if (!haveHeader)
        throw RunFileError(path, 0, nb::TrCore::tr("no header row (expected track,label,start_s,end_s,comment)"));
    return read;
}

Labels readLabelsFile(const QString& path)
{
    LabelsRead read = readLabels(path);
    if (!read.skipped.empty())
        throw read.skipped.front();
    return std::move(read.labels);
}

QStringList LabelsRead::problems() const
{
    QStringList out;
    for (const RunFileError& e : skipped)
        out << nb::TrCore::tr("%1: row skipped").arg(e.message());
    return out;
}

void writeLabelsFile(const QString& path, const Labels& labels)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        throw RunFileError(path, 0, nb::TrCore::tr("cannot write: %1").arg(file.errorString()));
    QByteArray out = "track,label,start_s,end_s,comment\n";
    for (const Label& l : labels)
        out += QStringLiteral("%1,%2,%3,%4,%5\n")
                   .arg(quoteIfNeeded(l.track), quoteIfNeeded(l.label))
                   .arg(l.start_s, 0, 'f', 6)
                   .arg(l.end_s, 0, 'f', 6)
                   .arg(quoteIfNeeded(l.comment))
                   .toUtf8();
    file.write(out);
    if (!commitWhole(file))
        throw RunFileError(path, 0, nb::TrCore::tr("cannot write: %1").arg(file.errorString()));
}

QStringList phasePerSample(const Labels& labels, const std::vector<double>& time_s, const QString& track)
{
    QStringList out;
    out.reserve(qsizetype(time_s.size()));
    for (double t : time_s) {
        QString name;
        for (const Label& l : labels) {
            if (!l.isPoint() && (track.isEmpty() || l.track == track) && l.contains(t)) {
                name = l.label;
                break;
            }
        }
        out << name;
    }
    return out;
}

QStringList overlappingLabels(const Labels& labels)
{
    QStringList out;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const Label& a = labels[i];
        if (a.isPoint())
            continue;
        for (std::size_t j = i + 1; j < labels.size(); ++j) {
            const Label& b = labels[j];
            if (b.isPoint() || b.track != a.track || b.start_s >= a.end_s || a.start_s >= b.end_s)
                continue;
            out << nb::TrCore::tr("labels '%1' (%2 s to %3 s) and '%4' (%5 s to %6 s) overlap on track '%7'; '%1' is taken where they do")
                       .arg(a.label)
                       .arg(a.start_s, 0, 'f', 3)
                       .arg(a.end_s, 0, 'f', 3)
                       .arg(b.label)
                       .arg(b.start_s, 0, 'f', 3)
                       .arg(b.end_s, 0, 'f', 3)
                       .arg(a.track);
        }
    }
    return out;
}

bool marksEvent(const Labels& labels, const QString& name)
{
    return std::any_of(labels.begin(), labels.end(),
                       [&](const Label& l) { return l.isPoint() && l.label.compare(name, Qt::CaseInsensitive) == 0; });
}

QString labelsPathFor(const QString& runPath)
{
    const QFileInfo fi(runPath);
    return fi.dir().filePath(fi.completeBaseName() + QStringLiteral(".labels.csv"));
}

}  // namespace nb
