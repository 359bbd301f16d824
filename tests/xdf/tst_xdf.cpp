// SPDX-License-Identifier: MIT
// `semhap export --xdf` read back by the reference reader, Debian's libxdf (docs/science.md):
// the streams and their channel labels, every sample, the markers in order, the clock
// offsets from the steady clock the session kept, and LSL's clock with --time lsl.
#include "clirun.h"
#include "sessionclock.h"
#include "sessionreader.h"
#include "xdfexport.h"
#include "xdfwriter.h"

#include <QBuffer>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QtTest>

#include <xdf.h>

#include <map>

using namespace semhap;

namespace {

/** A stream of a loaded file by its name; null when there is none. */
const Xdf::Stream *streamNamed(const Xdf &xdf, const std::string &name)
{
    for (const Xdf::Stream &stream : xdf.streams) {
        if (stream.info.name == name)
            return &stream;
    }
    return nullptr;
}

/** What the session holds, stream by stream, as the export names its streams. */
struct Expected
{
    std::map<std::string, std::vector<double>> stamps; ///< by stream name, in order
    std::vector<std::string> markers;                  ///< every gripper's, in order
    std::vector<double> firstRightForces;              ///< the first frame's 10 values
};

Expected expected(const QString &path, double (*toStamp)(const SessionClock &, double),
                  const SessionClock &clock)
{
    Expected e;
    QString error;
    auto session = SessionReader::open(path, &error);
    if (!session)
        return e;
    session->readContactFrames(
        [&](const ContactFrame &frame, double) {
            const std::string name =
                "semhap " + gripperName(frame.gripper).toStdString() + " gripper forces";
            if (e.stamps[name].empty() && frame.gripper == Gripper::Right) {
                for (const Fingertip *tip : {&frame.left, &frame.right}) {
                    e.firstRightForces.push_back(tip->f);
                    e.firstRightForces.push_back(tip->n);
                    for (double v : tip->fxyz)
                        e.firstRightForces.push_back(tip->hasFxyz ? v : qQNaN());
                }
            }
            e.stamps[name].push_back(toStamp(clock, frame.t));
            return true;
        },
        &error);
    session->readEvents(
        [&](const SemanticEvent &event) {
            e.stamps["semhap " + gripperName(event.gripper).toStdString() + " gripper events"]
                .push_back(toStamp(clock, event.t));
            e.markers.push_back(XdfExport::marker(messageName(event.message),
                                                  eventPhaseName(event.phase), event.intensity)
                                    .toStdString());
            return true;
        },
        &error);
    const QStringList devices = session->deviceNames();
    session->readDeviceFrames(
        [&](const DeviceFrame &frame) {
            e.stamps["semhap " + devices.at(frame.device).toStdString() + " output"].push_back(
                toStamp(clock, frame.t));
            return true;
        },
        &error);
    return e;
}

/**
 * A session time stamp as libxdf gives it back: it synchronises on load, adding the value of
 * the last clock offset collected before the stamp (the first offset's before them all).
 */
double sessionStamp(const SessionClock &clock, double t)
{
    size_t k = 0;
    while (k + 1 < clock.samples().size() && clock.samples()[k + 1].t < t)
        ++k;
    const SessionClock::Sample &s = clock.samples()[k];
    return t + (s.steady - s.t);
}

double lslStamp(const SessionClock &clock, double t)
{
    return clock.toSteady(t);
}

} // namespace

class TestXdf : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void libxdfReadsEveryStream_data();
    void libxdfReadsEveryStream();
    void simulationFasterThanRealTimeHasNoOffsets();
    void sessionWithoutTheClockCannotBeAligned();
    void lengthsTakeTheBytesTheyNeed();

private:
    QTemporaryDir m_dir;
    QString m_realTime; ///< a session recorded at real time
    QString m_fast;     ///< the same run as fast as it goes
};

void TestXdf::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_realTime = m_dir.filePath("realtime.db");
    m_fast = m_dir.filePath("fast.db");
    const QStringList run{"run",        "--scene",  "box_and_block", "--router", "C3",
                          "--operator", "scripted", "--duration",    "6",        "--seed",
                          "1"};
    CliResult r = semhapRun(run + QStringList{"--realtime", "--session", m_realTime});
    QVERIFY2(r.code == 0, r.err.constData());
    r = semhapRun(run + QStringList{"--session", m_fast});
    QVERIFY2(r.code == 0, r.err.constData());
}

void TestXdf::libxdfReadsEveryStream_data()
{
    QTest::addColumn<QString>("time");
    QTest::newRow("session time, clock offsets") << "session";
    QTest::newRow("LSL's clock") << "lsl";
}

void TestXdf::libxdfReadsEveryStream()
{
    QFETCH(QString, time);
    const QString file = m_dir.filePath(time + ".xdf");
    const CliResult r = semhapRun({"export", m_realTime, "--xdf", file, "--time", time});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.err.isEmpty(), r.err.constData()); // a real-time session lines up: no notes

    QString error;
    auto session = SessionReader::open(m_realTime, &error);
    QVERIFY2(session, qPrintable(error));
    SessionClock clock;
    QVERIFY(SessionClock::fromInfo(session->info(), &clock, &error));
    QVERIFY(clock.samples().size() >= 2); // the first frame's and the last's, 6 s apart
    QVERIFY(clock.followsClock());
    const bool lsl = time == "lsl";
    const Expected want = expected(m_realTime, lsl ? lslStamp : sessionStamp, clock);

    Xdf xdf;
    QCOMPARE(xdf.load_xdf(file.toStdString()), 0);
    QCOMPARE(xdf.version, 1.0f);
    // box_and_block has one gripper, and the scripted operator records no input: the left
    // gripper's streams and the hands' are left out, the seven devices each have one.
    QCOMPARE(int(xdf.streams.size()), int(want.stamps.size()));
    QVERIFY(!streamNamed(xdf, "semhap left gripper forces"));
    QVERIFY(!streamNamed(xdf, "semhap right hand input"));
    for (const auto &[name, stamps] : want.stamps) {
        const Xdf::Stream *stream = streamNamed(xdf, name);
        QVERIFY2(stream, name.c_str());
        QCOMPARE(stream->info.sample_count, int(stamps.size())); // the footer's
        if (stream->info.channel_format == "string") {
            // Markers go to the event map, with the stream they came in.
            std::vector<double> markerStamps;
            for (const auto &[event, index] : xdf.eventMap) {
                if (&xdf.streams[size_t(index)] == stream)
                    markerStamps.push_back(event.second);
            }
            QCOMPARE(markerStamps, stamps);
        } else {
            QCOMPARE(stream->time_stamps, stamps);
        }
        // One clock offset per sample of the steady clock: on the session's clock, what the
        // steady clock was ahead of it; on LSL's, nothing.
        QCOMPARE(stream->clock_times.size(), clock.samples().size());
        for (size_t i = 0; i < clock.samples().size(); ++i) {
            const SessionClock::Sample &s = clock.samples()[i];
            QCOMPARE(stream->clock_times[i], lsl ? s.steady : s.t);
            QCOMPARE(stream->clock_values[i], lsl ? 0.0 : s.steady - s.t);
        }
    }
    // The forces: float32 channels with their labels, the first frame's values.
    const Xdf::Stream *forces = streamNamed(xdf, "semhap right gripper forces");
    QCOMPARE(forces->info.channel_format, std::string("float32"));
    QCOMPARE(forces->info.channel_count, 10);
    QCOMPARE(forces->info.nominal_srate, 500.0); // box_and_block's 2 ms frames
    const char *labels[] = {"left_f",  "left_n",  "left_fx",  "left_fy",  "left_fz",
                            "right_f", "right_n", "right_fx", "right_fy", "right_fz"};
    for (int c = 0; c < 10; ++c) {
        QCOMPARE(forces->info.channels[size_t(c)].at("label"), std::string(labels[c]));
        const float value = forces->time_series[size_t(c)][0];
        const float wanted = float(want.firstRightForces[size_t(c)]);
        QVERIFY((std::isnan(value) && std::isnan(wanted)) || value == wanted);
    }
    // The markers, in order, with the stream they came in.
    std::vector<std::string> markers;
    for (const auto &[event, stream] : xdf.eventMap) {
        QCOMPARE(xdf.streams[size_t(stream)].info.type, std::string("Markers"));
        markers.push_back(event.first);
    }
    QVERIFY(!want.markers.empty());
    QCOMPARE(markers, want.markers);
    QVERIFY(markers.front().rfind("grasp/begin/", 0) == 0);
    // Either way the frames come back where the steady clock was when they were recorded,
    // seconds since boot; the file itself says which clock its stamps are on.
    QCOMPARE(forces->time_stamps.front(), clock.samples().front().steady);
    const double written = lsl ? clock.samples().front().steady : clock.samples().front().t;
    QVERIFY2(forces->streamFooter.find("<first_timestamp>" +
                                       QString::number(written, 'g', 17).toStdString() + "<") !=
                 std::string::npos,
             forces->streamFooter.c_str());
}

void TestXdf::simulationFasterThanRealTimeHasNoOffsets()
{
    // Simulated seconds are not the clock's: the export says so and writes no offsets, and
    // refuses LSL's clock.
    const QString file = m_dir.filePath("fast.xdf");
    CliResult r = semhapRun({"export", m_fast, "--xdf", file});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.err.startsWith((m_fast + ": no clock offsets: its time ran ").toUtf8()) &&
                 r.err.contains("times as fast as the clock (a simulation faster than real "
                                "time): its times are simulated seconds, so it cannot be "
                                "lined up with an LSL recording\n"),
             r.err.constData());
    Xdf xdf;
    QCOMPARE(xdf.load_xdf(file.toStdString()), 0);
    QVERIFY(!xdf.streams.empty());
    for (const Xdf::Stream &stream : xdf.streams)
        QVERIFY(stream.clock_times.empty());
    r = semhapRun({"export", m_fast, "--xdf", m_dir.filePath("fast-lsl.xdf"), "--time", "lsl"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains((m_fast + ": cannot be put on the LSL clock: its time ran ").toUtf8()),
             r.err.constData());
    QVERIFY(!QFileInfo::exists(m_dir.filePath("fast-lsl.xdf")));
}

void TestXdf::sessionWithoutTheClockCannotBeAligned()
{
    // A session of a semhap that did not keep the steady clock.
    const QString old = m_dir.filePath("old.db");
    QVERIFY(QFile::copy(m_realTime, old));
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "old");
        db.setDatabaseName(old);
        QVERIFY(db.open());
        QSqlQuery query(db);
        QVERIFY(query.exec("DELETE FROM metadata WHERE key = 'steady_clock'"));
        query.clear();
        db.close();
    }
    QSqlDatabase::removeDatabase("old");
    CliResult r = semhapRun({"export", old, "--xdf", m_dir.filePath("old.xdf"), "--time", "lsl"});
    QCOMPARE(r.code, 1);
    QCOMPARE(QString::fromUtf8(r.err).trimmed(),
             old + ": cannot be put on the LSL clock: it was recorded before sessions kept the "
                   "steady clock");
    r = semhapRun({"export", old, "--xdf", m_dir.filePath("old.xdf")});
    QCOMPARE(r.code, 0);
    QVERIFY(r.err.contains("no clock offsets: it was recorded before sessions kept the steady "
                           "clock"));
    // A usage error names the clocks.
    r = semhapRun({"export", old, "--xdf", m_dir.filePath("x.xdf"), "--time", "utc"});
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("--time: 'utc' is not a clock (session or lsl)"));
}

void TestXdf::lengthsTakeTheBytesTheyNeed()
{
    // A chunk's length is one byte up to 255, else four: a boundary chunk (16 bytes and the
    // tag) is 1 + 1 + 2 + 16 bytes; a samples chunk of 300 markers needs four length bytes.
    QByteArray bytes;
    QBuffer buffer(&bytes);
    QVERIFY(buffer.open(QIODevice::WriteOnly));
    XdfWriter writer(&buffer);
    QVERIFY(writer.writeBoundary());
    QCOMPARE(bytes.size(), 20);
    QCOMPARE(bytes.left(4), QByteArray::fromHex("01120500"));
    QCOMPARE(bytes.mid(4).toHex(), QByteArray("43a546dccbf5410fb30ed5467383cbe4"));
    bytes.clear();
    buffer.seek(0);
    std::vector<double> stamps(300, 1.5);
    QList<QByteArray> values(300, QByteArray("slip/begin/1.00"));
    QVERIFY(writer.writeStringSamples(7, stamps, values));
    // stream id 4, count 1 + 2 (300 = 0x012C needs four bytes: 1 + 4), each sample 1 + 8 + 1
    // + 1 + 15.
    const int content = 4 + 5 + 300 * (1 + 8 + 1 + 1 + 15);
    QCOMPARE(bytes.size(), 1 + 4 + 2 + content);
    QCOMPARE(quint8(bytes[0]), quint8(4));
    QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 1), quint32(content + 2));
}

QTEST_GUILESS_MAIN(TestXdf)
#include "tst_xdf.moc"
