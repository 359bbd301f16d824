// SPDX-License-Identifier: MIT
// `semhap route` on the bundled demo trace, for every preset: the events must be those of the
// independent reference (reference_events.py, written from the spec), the device frames those
// of the golden files beside this test (SEMHAP_REGENERATE_GOLDEN=1 rewrites them after a
// deliberate change; review the diff).
#include "clitool.h"
#include "jsonlines.h"

#include <QBuffer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace semhap;

namespace {

const QString Trace = QStringLiteral(SEMHAP_RESOURCES "/traces/demo.jsonl");

/** Keeps each device's first frame and every frame whose values differ from its previous. */
QList<QJsonObject> changes(const QList<QJsonObject> &frames)
{
    QHash<QString, QJsonValue> last;
    QList<QJsonObject> kept;
    for (const QJsonObject &frame : frames) {
        const QString device = frame.value("device").toString();
        if (!last.contains(device) || last.value(device) != frame.value("values")) {
            kept.append(frame);
            last.insert(device, frame.value("values"));
        }
    }
    return kept;
}

void writeLines(const QString &path, const QList<QJsonObject> &lines)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        qFatal("cannot write %s", qPrintable(path));
    for (const QJsonObject &line : lines)
        file.write(QJsonDocument(line).toJson(QJsonDocument::Compact) + '\n');
}

} // namespace

class TestRoute : public QObject
{
    Q_OBJECT

private slots:
    void demoTrace_data();
    void demoTrace();
    void eventsGoToStdout();
};

void TestRoute::demoTrace_data()
{
    QTest::addColumn<QString>("preset");
    for (const char *preset : {"none", "visual", "sensory", "C1", "C2", "C3", "C4"})
        QTest::newRow(preset) << QString::fromLatin1(preset);
}

void TestRoute::demoTrace()
{
    QFETCH(QString, preset);
    QTemporaryDir dir;
    const QString events = dir.filePath("events.jsonl");
    const QString frames = dir.filePath("frames.jsonl");
    QByteArray out;
    QByteArray err;
    QBuffer outBuffer(&out);
    QBuffer errBuffer(&err);
    outBuffer.open(QIODevice::WriteOnly);
    errBuffer.open(QIODevice::WriteOnly);
    {
        CliTool tool({nullptr, &outBuffer, &errBuffer});
        QCOMPARE(tool.run({"route", "--router", preset, "--frames", Trace, "--events", events,
                           "--device-frames", frames}),
                 0);
    }
    QCOMPARE(err, QByteArray());

    // Every preset runs the same detectors: the events do not depend on the routing.
    compareLines(readLines(events), readLines(SEMHAP_TEST_DATA "/demo.events.jsonl"));

    const QList<QJsonObject> all = readLines(frames);
    // Frames from 0 to 7.995 s: every instant k / rate <= 7.995 of each device: 800 at
    // 100 Hz (four devices), 3998 at 500 Hz (two), 480 at 60 Hz (the overlay).
    QCOMPARE(all.size(), 800 * 4 + 3998 * 2 + 480);
    const QString golden = QString(SEMHAP_TEST_DATA "/demo.%1.changes.jsonl").arg(preset);
    if (qEnvironmentVariableIsSet("SEMHAP_REGENERATE_GOLDEN"))
        writeLines(golden, changes(all));
    compareLines(changes(all), readLines(golden));
}

void TestRoute::eventsGoToStdout()
{
    QFile trace(Trace);
    QVERIFY(trace.open(QIODevice::ReadOnly));
    QByteArray out;
    QByteArray err;
    QBuffer outBuffer(&out);
    QBuffer errBuffer(&err);
    outBuffer.open(QIODevice::WriteOnly);
    errBuffer.open(QIODevice::WriteOnly);
    {
        CliTool tool({&trace, &outBuffer, &errBuffer});
        QCOMPARE(tool.run({"route", "--router", "C3", "--frames", "-", "--events", "-"}), 0);
    }
    QCOMPARE(out.count('\n'), qsizetype(readLines(SEMHAP_TEST_DATA "/demo.events.jsonl").size()));
    QVERIFY(err.isEmpty());
}

QTEST_GUILESS_MAIN(TestRoute)
#include "tst_route.moc"
