// The demo and export commands end to end, through the real executable as a user runs them.
#include "core/export/run_csv_export.h"
#include "core/labels.h"
#include "core/run_file.h"
#include "support/needlebench_cli.h"

#include <QDir>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <hdf5.h>

namespace {

nbtest::CliResult run(const QStringList& args)
{
    return nbtest::runCli(args);
}

}  // namespace

class TestDemoCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString demo_;
    nbtest::CliResult demoRun_;

private slots:
    // One demo for every function, made here so that each can be run alone.
    void initTestCase()
    {
        demo_ = QDir(dir_.path()).filePath(QStringLiteral("demo"));
        demoRun_ = run({QStringLiteral("demo"), QStringLiteral("--short"), QStringLiteral("--out"), demo_});
    }

    void demoRunsAShortSession()
    {
        const nbtest::CliResult& r = demoRun_;
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY(r.out.contains(QStringLiteral("simulated run_001_linear.csv")));
        QVERIFY(r.out.contains(QStringLiteral("Where everything went")));
        const QDir d(demo_);
        // 2 stiffness (liver1, liver2) + 1 friction run in the short session.
        const QStringList runs = QDir(d.filePath(QStringLiteral("session"))).entryList({QStringLiteral("run_*.csv")}, QDir::Files);
        QCOMPARE(runs.filter(QStringLiteral(".labels.")).size(), 3);
        const QStringList csvs = QDir(d.filePath(QStringLiteral("csv"))).entryList({QStringLiteral("*.json")}, QDir::Files);
        QCOMPARE(csvs.size(), 3);

        // Labels are the ones suggested from the data, not the simulator's record.
        QVERIFY2(r.out.contains(QRegularExpression(QStringLiteral("labelled run_001_linear.csv: \\d+ suggested labels"))), qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(QStringLiteral("labelled run_003_sine.csv: \\d+ suggested labels \\(phases a, b1, b2, c per "
                                                                  "half-cycle, checked against the tissue's motion in run_003_sine.avi\\)"))),
                 qPrintable(r.out));
        const nb::Labels sineLabels = nb::readLabelsFile(d.filePath(QStringLiteral("session/run_003_sine.labels.csv")));
        QVERIFY(sineLabels.size() >= 8);  // a, b1, b2, c over several half-cycles
        // The run has its imaging video: the phases went through the tissue's motion in it.
        QVERIFY(std::any_of(sineLabels.begin(), sineLabels.end(),
                            [](const nb::Label& l) { return l.comment.contains(QLatin1String("tissue's motion in run_003_sine.avi")); }));
        QStringList phases;
        for (const nb::Label& l : sineLabels) {
            QVERIFY2(l.comment.startsWith(QLatin1String("suggested")), qPrintable(l.comment));  // and what from
            phases << l.label;
        }
        for (const char* phase : {"a", "b1", "b2", "c"})
            QVERIFY2(phases.contains(QLatin1String(phase)), phase);
        const nb::Labels events = nb::readLabelsFile(d.filePath(QStringLiteral("session/run_001_linear.labels.csv")));
        QVERIFY(std::any_of(events.begin(), events.end(), [](const nb::Label& l) { return l.label == QLatin1String("puncture"); }));

        // The friction run has its imaging video, a real file a user's tools open, as long as the run.
        const QString video = d.filePath(QStringLiteral("session/run_003_sine.avi"));
        const nbtest::CliResult vi = run({QStringLiteral("video-info"), QStringLiteral("--json"), video});
        QVERIFY2(vi.code == 0, qPrintable(vi.err));
        const QJsonObject v = QJsonDocument::fromJson(vi.out.toUtf8()).object();
        const nb::Run sine = nb::readRunFile(d.filePath(QStringLiteral("session/run_003_sine.csv"))).run;
        const double runDuration = sine.time_s.back() - sine.time_s.front();
        QVERIFY(runDuration > 5.0);  // 3 cycles at 0.5 Hz
        const int frames = v.value(QStringLiteral("frames")).toInt();
        // The video starts before the recording and runs on after it: at most ~2 s more.
        QVERIFY2(frames >= runDuration * 29.97 && frames <= (runDuration + 2.0) * 29.97,
                 qPrintable(QStringLiteral("%1 frames for %2 s").arg(frames).arg(runDuration)));
        QVERIFY(std::abs(v.value(QStringLiteral("duration_s")).toDouble() * 29.97 - frames) < 2.0);

        // The video was synchronised: the offset found is within two frames of the truth the
        // demo reports, and the run file names the video.
        const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("sync offset (-?[0-9.]+) s found, (-?[0-9.]+) s true")).match(r.out);
        QVERIFY2(m.hasMatch(), qPrintable(r.out));
        const double found = m.captured(1).toDouble(), truth = m.captured(2).toDouble();
        QVERIFY2(std::abs(found - truth) < 2.0 / 29.97, qPrintable(m.captured(0)));
        QCOMPARE(sine.meta(QStringLiteral("video_file")).value_or(QString()), QStringLiteral("run_003_sine.avi"));
        QVERIFY(std::abs(sine.metadata.number(QStringLiteral("sync_offset_s")).value_or(-1.0) - found) < 0.0015);
        QFile sidecar(d.filePath(QStringLiteral("csv/run_003_sine.json")));
        QVERIFY(sidecar.open(QIODevice::ReadOnly));
        const QJsonObject sync = QJsonDocument::fromJson(sidecar.readAll()).object().value(QStringLiteral("sync")).toObject();
        QVERIFY(std::abs(sync.value(QStringLiteral("offset_s")).toDouble() - found) < 0.0015);
        QCOMPARE(sync.value(QStringLiteral("video_file")).toString(), QStringLiteral("run_003_sine.avi"));

        // The HDF5 file holds the three runs with their forces.
        const hid_t f = H5Fopen(QFile::encodeName(d.filePath(QStringLiteral("session.h5"))).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
        QVERIFY(f >= 0);
        const hid_t g = H5Gopen2(f, "/runs", H5P_DEFAULT);
        H5G_info_t info;
        QVERIFY(H5Gget_info(g, &info) >= 0);
        QCOMPARE(int(info.nlinks), 3);
        H5Gclose(g);
        // ... and the sine run carries its video's name and sync offset as attributes.
        const hid_t sg = H5Gopen2(f, "/runs/run_003_sine", H5P_DEFAULT);
        QVERIFY(sg >= 0);
        double offset = -1.0;
        const hid_t oa = H5Aopen(sg, "sync_offset_s", H5P_DEFAULT);
        QVERIFY(oa >= 0);
        QVERIFY(H5Aread(oa, H5T_NATIVE_DOUBLE, &offset) >= 0);
        H5Aclose(oa);
        QVERIFY(std::abs(offset - found) < 0.0015);
        const hid_t va = H5Aopen(sg, "video_file", H5P_DEFAULT);
        QVERIFY(va >= 0);
        // Fixed-length strings (what Octave and MATLAB read).
        const hid_t strType = H5Aget_type(va);
        QCOMPARE(H5Tis_variable_str(strType), 0);
        std::vector<char> name(H5Tget_size(strType) + 1, '\0');
        QVERIFY(H5Aread(va, strType, name.data()) >= 0);
        QCOMPARE(QString::fromUtf8(name.data()), QStringLiteral("run_003_sine.avi"));
        H5Tclose(strType);
        H5Aclose(va);
        H5Gclose(sg);
        H5Fclose(f);

        // Stiffness tables: the pooled fits of both livers, with positive puncture forces.
        QFile pooled(d.filePath(QStringLiteral("tables/stiffness_pooled.csv")));
        QVERIFY(pooled.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = pooled.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 5);  // header + (pooled, mean) x 2 livers
        QVERIFY(lines[1].startsWith("liver1,"));
        QVERIFY(lines[3].startsWith("liver2,"));
        QVERIFY(lines[1].split(',').at(6).toDouble() > 0.2);
        QVERIFY(QFileInfo::exists(d.filePath(QStringLiteral("tables/friction_summary.tex"))));

        // Figures: real PNGs with something drawn.
        const QStringList pngs = QDir(d.filePath(QStringLiteral("figures"))).entryList({QStringLiteral("*.png")}, QDir::Files);
        QVERIFY2(pngs.size() >= 6, qPrintable(pngs.join(QLatin1Char(' '))));
        for (const QString& png : pngs) {
            const QImage img(d.filePath(QStringLiteral("figures/") + png));
            QVERIFY2(!img.isNull() && img.width() >= 600, qPrintable(png));
            // A journal takes vector figures: PDF and SVG beside every PNG.
            const QString base = d.filePath(QStringLiteral("figures/") + QFileInfo(png).completeBaseName());
            QVERIFY2(QFileInfo(base + QStringLiteral(".pdf")).size() > 0, qPrintable(png));
            QVERIFY2(QFileInfo(base + QStringLiteral(".svg")).size() > 0, qPrintable(png));
        }
    }

    void demoRefusesAUsedFolder()
    {
        const nbtest::CliResult r = run({QStringLiteral("demo"), QStringLiteral("--short"), QStringLiteral("--out"), demo_});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("is not empty")), qPrintable(r.err));
        // A folder without a session/ (an earlier demo's exports, a lab's tables) is kept too:
        // its session.h5 and tables were replaced.
        const QString other = dir_.filePath(QStringLiteral("not_a_demo"));
        QVERIFY(QDir().mkpath(other));
        {
            QFile h5(QDir(other).filePath(QStringLiteral("session.h5")));
            QVERIFY(h5.open(QIODevice::WriteOnly));
            h5.write("kept");
        }
        const nbtest::CliResult again = run({QStringLiteral("demo"), QStringLiteral("--short"), QStringLiteral("--out"), other});
        QCOMPARE(again.code, 1);
        QVERIFY2(again.err.contains(other), qPrintable(again.err));
        QCOMPARE(QFileInfo(QDir(other).filePath(QStringLiteral("session.h5"))).size(), 4);
        QVERIFY(!QFileInfo::exists(QDir(other).filePath(QStringLiteral("session"))));
    }

    void exportEveryFormatFromTheDemoSession()
    {
        const QString session = QDir(demo_).filePath(QStringLiteral("session"));
        const QDir out(dir_.filePath(QStringLiteral("exported")));
        nbtest::CliResult r = run({QStringLiteral("export"), session, QStringLiteral("--format"), QStringLiteral("csv"), QStringLiteral("--out"),
                        out.filePath(QStringLiteral("csv"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QString csv = out.filePath(QStringLiteral("csv/run_001_linear.csv"));
        QFile json(nb::sidecarPath(csv));
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonObject j = QJsonDocument::fromJson(json.readAll()).object();
        QCOMPARE(j.value(QStringLiteral("metadata")).toObject().value(QStringLiteral("tissue")).toObject().value(QStringLiteral("value")).toString(),
                 QStringLiteral("liver1"));
        QVERIFY(QFileInfo::exists(out.filePath(QStringLiteral("csv/run_001_linear.intervals.csv"))));

        r = run({QStringLiteral("export"), session, QStringLiteral("--format"), QStringLiteral("hdf5"), QStringLiteral("--out"),
                 out.filePath(QStringLiteral("all.h5"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("[3/3]")));
        QVERIFY(H5Fis_hdf5(QFile::encodeName(out.filePath(QStringLiteral("all.h5"))).constData()) > 0);

        r = run({QStringLiteral("export"), session, QStringLiteral("--format"), QStringLiteral("eaf"), QStringLiteral("--out"),
                 out.filePath(QStringLiteral("eaf"))});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile eaf(out.filePath(QStringLiteral("eaf/run_003_sine.eaf")));
        QVERIFY(eaf.open(QIODevice::ReadOnly));
        QXmlStreamReader x(&eaf);
        int tiers = 0;
        while (!x.atEnd())
            if (x.readNext() == QXmlStreamReader::StartElement && x.name() == u"TIER")
                ++tiers;
        QVERIFY(!x.hasError());
        QVERIFY(tiers >= 1);
    }

    void exportRejectsBadArguments()
    {
        nbtest::CliResult r = run({QStringLiteral("export"), demo_, QStringLiteral("--format"), QStringLiteral("xlsx"), QStringLiteral("--out"), QStringLiteral("x")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains(QStringLiteral("unknown format 'xlsx'")));
        r = run({QStringLiteral("export"), demo_, QStringLiteral("--format"), QStringLiteral("csv")});
        QCOMPARE(r.code, 2);
        r = run({QStringLiteral("export"), QStringLiteral("/nonexistent-nb-session"), QStringLiteral("--format"), QStringLiteral("csv"),
                 QStringLiteral("--out"), dir_.filePath(QStringLiteral("never"))});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("/nonexistent-nb-session")));
        QVERIFY(!QFileInfo::exists(dir_.filePath(QStringLiteral("never"))));
        // A folder with no runs says so.
        QDir().mkpath(dir_.filePath(QStringLiteral("empty")));
        r = run({QStringLiteral("export"), dir_.filePath(QStringLiteral("empty")), QStringLiteral("--format"), QStringLiteral("hdf5"),
                 QStringLiteral("--out"), dir_.filePath(QStringLiteral("e.h5"))});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("no run files")));
    }
};

QTEST_GUILESS_MAIN(TestDemoCli)
#include "test_demo_cli.moc"
