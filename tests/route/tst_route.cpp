// SPDX-License-Identifier: MIT
// `semhap route` on the bundled demo trace, for every preset: the events must be those of the
// independent reference (reference_events.py, written from the spec), the device frames those
// of the golden files beside this test (SEMHAP_REGENERATE_GOLDEN=1 rewrites them after a
// deliberate change; review the diff).
#include "clitool.h"

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

QList<QJsonObject> readLines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    QList<QJsonObject> lines;
    while (!file.atEnd()) {
        const QByteArray line = file.readLine().trimmed();
        if (!line.isEmpty())
            lines.append(QJsonDocument::fromJson(line).object());
    }
    return lines;
}

bool sameValue(const QJsonValue &a, const QJsonValue &b)
{
    if (a.isDouble() && b.isDouble())
        return std::abs(a.toDouble() - b.toDouble()) <=
               1e-9 * std::max(1.0, std::abs(a.toDouble()));
    if (a.isArray() && b.isArray()) {
        const QJsonArray x = a.toArray();
        const QJsonArray y = b.toArray();
        if (x.size() != y.size())
            return false;
        for (int i = 0; i < x.size(); ++i) {
            if (!sameValue(x[i], y[i]))
                return false;
        }
        return true;
    }
    return a == b;
}

/** Compares parsed lines key by key, numbers to 1e-9; names the first difference. */
void compareLines(const QList<QJsonObject> &actual, const QList<QJsonObject> &expected)
{
    const int n = int(std::min(actual.size(), expected.size()));
    for (int i = 0; i < n; ++i) {
        const QJsonObject &a = actual[i];
        const QJsonObject &e = expected[i];
        bool same = a.keys() == e.keys();
        for (auto it = e.begin(); same && it != e.end(); ++it)
            same = sameValue(a.value(it.key()), it.value());
        if (!same)
            QFAIL(qPrintable(
                QString("line %1 differs:\n  actual:   %2\n  expected: %3")
                    .arg(i + 1)
                    .arg(QString::fromUtf8(QJsonDocument(a).toJson(QJsonDocument::Compact)),
                         QString::fromUtf8(QJsonDocument(e).toJson(QJsonDocument::Compact)))));
    }
    QCOMPARE(actual.size(), expected.size());
}

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
