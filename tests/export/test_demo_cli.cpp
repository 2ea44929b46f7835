// The demo and export commands end to end, through the real executable as a user runs them.
#include "core/export/run_csv_export.h"

#include <QDir>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>
#include <hdf5.h>

namespace {

struct Result {
    int code;
    QString out, err;
};

Result run(const QStringList& args)
{
    QProcess p;
    auto env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("DISPLAY"));  // must not need a display
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(NB_EXECUTABLE), args);
    if (!p.waitForFinished(120000))
        qFatal("needlebench did not finish");
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()), QString::fromUtf8(p.readAllStandardError())};
}

}  // namespace

class TestDemoCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString demo_;

private slots:
    void initTestCase() { demo_ = QDir(dir_.path()).filePath(QStringLiteral("demo")); }

    void demoRunsAShortSession()
    {
        const Result r = run({QStringLiteral("demo"), QStringLiteral("--short"), QStringLiteral("--out"), demo_});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY(r.out.contains(QStringLiteral("simulated run_001_linear.csv")));
        QVERIFY(r.out.contains(QStringLiteral("Where everything went")));
        const QDir d(demo_);
        // 2 stiffness (liver1, liver2) + 1 friction run in the short session.
        const QStringList runs = QDir(d.filePath(QStringLiteral("session"))).entryList({QStringLiteral("run_*.csv")}, QDir::Files);
        QCOMPARE(runs.filter(QStringLiteral(".labels.")).size(), 3);
        const QStringList csvs = QDir(d.filePath(QStringLiteral("csv"))).entryList({QStringLiteral("*.json")}, QDir::Files);
        QCOMPARE(csvs.size(), 3);

        // The HDF5 file holds the three runs with their forces.
        const hid_t f = H5Fopen(QFile::encodeName(d.filePath(QStringLiteral("session.h5"))).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
        QVERIFY(f >= 0);
        const hid_t g = H5Gopen2(f, "/runs", H5P_DEFAULT);
        H5G_info_t info;
        QVERIFY(H5Gget_info(g, &info) >= 0);
        QCOMPARE(int(info.nlinks), 3);
        H5Gclose(g);
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
        }
    }

    void demoRefusesAUsedFolder()
    {
        const Result r = run({QStringLiteral("demo"), QStringLiteral("--short"), QStringLiteral("--out"), demo_});
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("already holds a session")));
    }

    void exportEveryFormatFromTheDemoSession()
    {
        const QString session = QDir(demo_).filePath(QStringLiteral("session"));
        const QDir out(dir_.filePath(QStringLiteral("exported")));
        Result r = run({QStringLiteral("export"), session, QStringLiteral("--format"), QStringLiteral("csv"), QStringLiteral("--out"),
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
        Result r = run({QStringLiteral("export"), demo_, QStringLiteral("--format"), QStringLiteral("xlsx"), QStringLiteral("--out"), QStringLiteral("x")});
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
