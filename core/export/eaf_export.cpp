#include "eaf_export.h"

#include "csv_text.h"

#include <QDateTime>
#include <QFileInfo>
#include <QMimeDatabase>
#include <QUrl>
#include <QXmlStreamWriter>
#include <cmath>
#include <map>

namespace nb {

namespace {

QString fileUrl(const QString& path) { return QUrl::fromLocalFile(QFileInfo(path).absoluteFilePath()).toString(); }

qint64 ms(double s) { return qint64(std::llround(s * 1000.0)); }

// ELAN's relative URLs: "./name" beside the document, "../x/name" elsewhere. Without the
// document's place only the file name can be given.
QString relativeUrl(const QString& documentPath, const QString& target)
{
    const QString rel = documentPath.isEmpty() ? QFileInfo(target).fileName() : relativeLink(documentPath, target);
    return rel.startsWith(QLatin1String("../")) ? rel : QStringLiteral("./") + rel;
}

}  // namespace

QByteArray eafDocument(const DatasetRun& r, const EafLinks& links)
{
    QByteArray bytes;
    QXmlStreamWriter x(&bytes);
    x.setAutoFormatting(true);
    x.writeStartDocument();
    x.writeStartElement(QStringLiteral("ANNOTATION_DOCUMENT"));
    x.writeAttribute(QStringLiteral("AUTHOR"), QStringLiteral("NeedleBench"));
    const QDateTime now = QDateTime::currentDateTime();
    x.writeAttribute(QStringLiteral("DATE"), now.toOffsetFromUtc(now.offsetFromUtc()).toString(Qt::ISODate));
    x.writeAttribute(QStringLiteral("FORMAT"), QStringLiteral("3.0"));
    x.writeAttribute(QStringLiteral("VERSION"), QStringLiteral("3.0"));
    x.writeNamespace(QStringLiteral("http://www.w3.org/2001/XMLSchema-instance"), QStringLiteral("xsi"));
    x.writeAttribute(QStringLiteral("http://www.w3.org/2001/XMLSchema-instance"), QStringLiteral("noNamespaceSchemaLocation"),
                     QStringLiteral("http://www.mpi.nl/tools/elan/EAFv3.0.xsd"));

    x.writeStartElement(QStringLiteral("HEADER"));
    x.writeAttribute(QStringLiteral("MEDIA_FILE"), QString());
    x.writeAttribute(QStringLiteral("TIME_UNITS"), QStringLiteral("milliseconds"));
    if (!links.videoPath.isEmpty()) {
        x.writeEmptyElement(QStringLiteral("MEDIA_DESCRIPTOR"));
        x.writeAttribute(QStringLiteral("MEDIA_URL"), fileUrl(links.videoPath));
        x.writeAttribute(QStringLiteral("RELATIVE_MEDIA_URL"), relativeUrl(links.documentPath, links.videoPath));
        x.writeAttribute(QStringLiteral("MIME_TYPE"), QMimeDatabase().mimeTypeForFile(links.videoPath, QMimeDatabase::MatchExtension).name());
        // ELAN's TIME_ORIGIN is where in the media file annotation time 0 lies.
        const qint64 origin = ms(syncOffset(r.run));
        if (origin != 0)
            x.writeAttribute(QStringLiteral("TIME_ORIGIN"), QString::number(origin));
    }
    if (!links.forceCsvPath.isEmpty()) {
        x.writeEmptyElement(QStringLiteral("LINKED_FILE_DESCRIPTOR"));
        x.writeAttribute(QStringLiteral("LINK_URL"), fileUrl(links.forceCsvPath));
        x.writeAttribute(QStringLiteral("RELATIVE_LINK_URL"), relativeUrl(links.documentPath, links.forceCsvPath));
        x.writeAttribute(QStringLiteral("MIME_TYPE"), QStringLiteral("text/csv"));
        x.writeAttribute(QStringLiteral("TIME_ORIGIN"), QStringLiteral("0"));
    }
    // Labels get ids a1..aN; a comment becomes a symbolic child annotation a(N+1)...
    qsizetype commentCount = 0;
    for (const Label& l : r.labels)
        commentCount += l.comment.isEmpty() ? 0 : 1;
    const qsizetype annotationCount = qsizetype(r.labels.size()) + commentCount;
    // The run's place in an experiment plan (factor levels, plan name and run number), so a
    // document opened on its own in ELAN still says which condition it shows.
    for (const auto& [key, value] : r.run.metadata.entries()) {
        if (!key.startsWith(QLatin1String("factor_")) && !key.startsWith(QLatin1String("plan_")))
            continue;
        x.writeStartElement(QStringLiteral("PROPERTY"));
        x.writeAttribute(QStringLiteral("NAME"), key);
        x.writeCharacters(value);
        x.writeEndElement();
    }
    x.writeStartElement(QStringLiteral("PROPERTY"));
    x.writeAttribute(QStringLiteral("NAME"), QStringLiteral("lastUsedAnnotationId"));
    x.writeCharacters(QString::number(annotationCount));
    x.writeEndElement();
    x.writeEndElement();  // HEADER

    // One time slot per distinct millisecond keeps the document small and ELAN happy.
    std::map<qint64, QString> timeSlots;
    for (const Label& l : r.labels) {
        const qint64 a = ms(l.start_s);
        const qint64 b = std::max(ms(l.end_s), a + 1);
        timeSlots.emplace(a, QString());
        timeSlots.emplace(b, QString());
    }
    int k = 0;
    for (auto& [t, id] : timeSlots)
        id = QStringLiteral("ts%1").arg(++k);
    x.writeStartElement(QStringLiteral("TIME_ORDER"));
    for (const auto& [t, id] : timeSlots) {
        x.writeEmptyElement(QStringLiteral("TIME_SLOT"));
        x.writeAttribute(QStringLiteral("TIME_SLOT_ID"), id);
        x.writeAttribute(QStringLiteral("TIME_VALUE"), QString::number(t));
    }
    x.writeEndElement();

    int a = 0;
    const QStringList tracks = labelTracks(r.labels);
    std::map<const Label*, int> ids;
    for (const QString& track : tracks) {
        x.writeStartElement(QStringLiteral("TIER"));
        x.writeAttribute(QStringLiteral("LINGUISTIC_TYPE_REF"), QStringLiteral("label"));
        x.writeAttribute(QStringLiteral("TIER_ID"), track);
        for (const Label& l : r.labels) {
            if (l.track != track)
                continue;
            const qint64 t0 = ms(l.start_s);
            const qint64 t1 = std::max(ms(l.end_s), t0 + 1);
            x.writeStartElement(QStringLiteral("ANNOTATION"));
            x.writeStartElement(QStringLiteral("ALIGNABLE_ANNOTATION"));
            ids[&l] = ++a;
            x.writeAttribute(QStringLiteral("ANNOTATION_ID"), QStringLiteral("a%1").arg(a));
            x.writeAttribute(QStringLiteral("TIME_SLOT_REF1"), timeSlots.at(t0));
            x.writeAttribute(QStringLiteral("TIME_SLOT_REF2"), timeSlots.at(t1));
            x.writeTextElement(QStringLiteral("ANNOTATION_VALUE"), l.label);
            x.writeEndElement();
            x.writeEndElement();
        }
        x.writeEndElement();
    }
    // Comments live on a child tier per track, each tied to its label (ELAN's symbolic association).
    for (const QString& track : tracks) {
        bool any = false;
        for (const Label& l : r.labels)
            any = any || (l.track == track && !l.comment.isEmpty());
        if (!any)
            continue;
        x.writeStartElement(QStringLiteral("TIER"));
        x.writeAttribute(QStringLiteral("LINGUISTIC_TYPE_REF"), QStringLiteral("comment"));
        x.writeAttribute(QStringLiteral("PARENT_REF"), track);
        x.writeAttribute(QStringLiteral("TIER_ID"), track + QStringLiteral(" comment"));
        for (const Label& l : r.labels) {
            if (l.track != track || l.comment.isEmpty())
                continue;
            x.writeStartElement(QStringLiteral("ANNOTATION"));
            x.writeStartElement(QStringLiteral("REF_ANNOTATION"));
            x.writeAttribute(QStringLiteral("ANNOTATION_ID"), QStringLiteral("a%1").arg(++a));
            x.writeAttribute(QStringLiteral("ANNOTATION_REF"), QStringLiteral("a%1").arg(ids.at(&l)));
            x.writeTextElement(QStringLiteral("ANNOTATION_VALUE"), l.comment);
            x.writeEndElement();
            x.writeEndElement();
        }
        x.writeEndElement();
    }
    x.writeEmptyElement(QStringLiteral("LINGUISTIC_TYPE"));
    x.writeAttribute(QStringLiteral("GRAPHIC_REFERENCES"), QStringLiteral("false"));
    x.writeAttribute(QStringLiteral("LINGUISTIC_TYPE_ID"), QStringLiteral("label"));
    x.writeAttribute(QStringLiteral("TIME_ALIGNABLE"), QStringLiteral("true"));
    x.writeEmptyElement(QStringLiteral("LINGUISTIC_TYPE"));
    x.writeAttribute(QStringLiteral("CONSTRAINTS"), QStringLiteral("Symbolic_Association"));
    x.writeAttribute(QStringLiteral("GRAPHIC_REFERENCES"), QStringLiteral("false"));
    x.writeAttribute(QStringLiteral("LINGUISTIC_TYPE_ID"), QStringLiteral("comment"));
    x.writeAttribute(QStringLiteral("TIME_ALIGNABLE"), QStringLiteral("false"));
    x.writeEmptyElement(QStringLiteral("CONSTRAINT"));
    x.writeAttribute(QStringLiteral("DESCRIPTION"),
                     QStringLiteral("1-1 association with a parent annotation"));
    x.writeAttribute(QStringLiteral("STEREOTYPE"), QStringLiteral("Symbolic_Association"));
    x.writeEndElement();  // ANNOTATION_DOCUMENT
    x.writeEndDocument();
    return bytes;
}

void writeEaf(const QString& path, const DatasetRun& run, const EafLinks& links)
{
    EafLinks placed = links;
    placed.documentPath = path;
    writeFileAtomically(path, eafDocument(run, placed));
}

}  // namespace nb
