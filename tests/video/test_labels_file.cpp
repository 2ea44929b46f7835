// core/labels: the labels file `track,label,start_s,end_s,comment` on real files.
#include "core/labels.h"
#include "core/run_file.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

class TestLabelsFile : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    QString write(const QString& name, const QByteArray& text)
    {
        QFile f(dir_.filePath(name));
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return f.fileName();
    }

private slots:
    void roundTrip()
    {
        const nb::Labels labels{{"insertion", "a", 0.5, 0.75, ""},
                                {"withdrawal", "c", 1.25, 2.0, "operator: slipped, \"twice\""},
                                {"events", "puncture", 3.0, 3.0, "peak"}};
        const QString path = dir_.filePath("r.labels.csv");
        nb::writeLabelsFile(path, labels);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readLine().startsWith("track,label,start_s,end_s,comment"));
        QCOMPARE(nb::readLabelsFile(path), labels);
        QVERIFY(labels[2].isPoint());
    }

    void acceptsCrlfBomCommentsAndColumnOrder()
    {
        const QString p = write("x.csv", "\xEF\xBB\xBF# made by hand\r\nlabel,track,end_s,start_s\r\nb1,insertion,2,1\r\n\r\n");
        const nb::Labels l = nb::readLabelsFile(p);
        QCOMPARE(l.size(), std::size_t(1));
        QCOMPARE(l[0].label, QStringLiteral("b1"));
        QCOMPARE(l[0].start_s, 1.0);
        QCOMPARE(l[0].end_s, 2.0);
    }

    void badFilesNameFileAndLine()
    {
        struct Case {
            QByteArray text;
            int line;
            const char* reason;
        };
        const Case cases[] = {{"track,label,start_s,end_s,comment\ni,a,1,x,\n", 2, "numbers"},
                              {"track,label,start_s,end_s\ni,a,2,1\n", 2, "before"},
                              {"track,label,start_s\n", 1, "end_s"},
                              {"track,label,start_s,end_s\ni,,1,2\n", 2, "empty label"},
                              {"", 0, "no header"}};
        int k = 0;
        for (const Case& c : cases) {
            const QString p = write(QStringLiteral("bad%1.csv").arg(k++), c.text);
            try {
                nb::readLabelsFile(p);
                QFAIL(c.reason);
            } catch (const nb::RunFileError& e) {
                QCOMPARE(e.file(), p);
                QCOMPARE(e.line(), c.line);
                QVERIFY2(e.reason().contains(QLatin1String(c.reason)), qPrintable(e.reason()));
            }
        }
        QVERIFY_THROWS_EXCEPTION(nb::RunFileError, nb::readLabelsFile(dir_.filePath("missing.csv")));
    }

    void phasePerSample()
    {
        const nb::Labels labels{{"insertion", "a", 0.0, 1.0, ""}, {"insertion", "c", 1.0, 2.0, ""},
                                {"withdrawal", "a", 2.0, 3.0, ""}, {"events", "puncture", 1.5, 1.5, ""}};
        const std::vector<double> t{-0.5, 0.0, 0.99, 1.0, 1.5, 2.5, 3.0};
        QCOMPARE(nb::phasePerSample(labels, t), (QStringList{"", "a", "a", "c", "c", "a", ""}));
        QCOMPARE(nb::phasePerSample(labels, t, "insertion"), (QStringList{"", "a", "a", "c", "c", "", ""}));
    }
};

QTEST_GUILESS_MAIN(TestLabelsFile)
#include "test_labels_file.moc"
