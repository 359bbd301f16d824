// SPDX-License-Identifier: MIT
// The sound card transport without a sound card: PortAudio's ALSA host API plays into
// PCMs of a test-local ALSA configuration, whose `file` plugin writes the raw samples into
// a FIFO that a reader drains at the card's rate (FifoCard). What the card got is checked: the
// carrier's frequency, the envelope's level, which output each channel is on, no steps at
// envelope changes, silence after stop-all, disarming and close, what sent() says, and a
// card that goes away mid-stream and comes back; and `semhap devices` and `semhap play` on it.
#include "audiosystem.h"
#include "audiotransport.h"
#include "devicemanager.h"
#include "fifocard.h"
#include "transportfactory.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace semhap;

namespace {

constexpr double Rate = FifoCard::Rate;

DeviceFrame frameOf(double t, std::initializer_list<double> values)
{
    DeviceFrame f;
    f.t = t;
    f.channelCount = int(values.size());
    std::copy(values.begin(), values.end(), f.values.begin());
    return f;
}

/** The steady middle of a burst: from 20 ms after the first sample above half of `level`
 * to 20 ms before the last. */
std::vector<float> steadyPart(const std::vector<float> &samples, double level)
{
    const auto loud = [level](float x) { return std::abs(x) > 0.5 * level; };
    const auto first = std::find_if(samples.begin(), samples.end(), loud);
    const auto last = std::find_if(samples.rbegin(), samples.rend(), loud).base();
    const long margin = long(0.02 * Rate);
    if (last - first < 3 * margin)
        return {};
    return std::vector<float>(first + margin, last - margin);
}

/** Frequency by the rising zero crossings, interpolated between samples. */
double frequency(const std::vector<float> &samples)
{
    double firstCrossing = -1.0;
    double lastCrossing = -1.0;
    int crossings = 0;
    for (size_t i = 1; i < samples.size(); ++i) {
        if (samples[i - 1] < 0.0f && samples[i] >= 0.0f) {
            const double at =
                double(i - 1) + double(samples[i - 1]) / double(samples[i - 1] - samples[i]);
            if (firstCrossing < 0.0)
                firstCrossing = at;
            lastCrossing = at;
            ++crossings;
        }
    }
    return crossings > 1 ? (crossings - 1) * Rate / (lastCrossing - firstCrossing) : 0.0;
}

/**
 * The most one sample of a 170 Hz carrier may move with the envelope at most `level` and
 * changing by at most `envelopeStep` a sample: more is a step, heard as a click.
 */
double smoothStep(double level, double envelopeStep)
{
    return 2.0 * M_PI * 170.0 / Rate * level + envelopeStep + 1e-6;
}

/** The largest change between neighbouring samples from `from` on. */
double largestStep(const std::vector<float> &samples, size_t from)
{
    double out = 0.0;
    for (size_t i = std::max<size_t>(from, 1); i < samples.size(); ++i)
        out = std::max(out, double(std::abs(samples[i] - samples[i - 1])));
    return out;
}

float peak(const std::vector<float> &samples)
{
    float out = 0.0f;
    for (const float x : samples)
        out = std::max(out, std::abs(x));
    return out;
}

/** Waits until `card` has got `seconds` more of the stream (the card's time). */
bool playFor(const FifoCard &card, double seconds)
{
    const size_t from = card.frames();
    return QTest::qWaitFor([&] { return card.frames() > from + size_t(seconds * Rate); }, 10000);
}

} // namespace

class TestAudio : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void outputsAreListed();
    void badAddressesAreRejected_data();
    void badAddressesAreRejected();
    void carrierAndEnvelope_data();
    void carrierAndEnvelope();
    void channelsGoWhereMapped();
    void envelopeStepsAreRamped();
    void stopAllSilencesAtOnce();
    void aValueSentAfterStopAllPlays();
    void disarmingSilencesHeldValues();
    void closeLeavesSilence();
    void vanishedCardIsRetried();
    void devicesCommandListsOutputs();
    void playCommandPlaysOnTheCard();

private:
    std::unique_ptr<AudioTransport> open(const QString &uri, const QString &model = "lra4");
    /** Armed on the test card, `level` on every channel (frame time `t`) for 0.2 s. */
    std::unique_ptr<AudioTransport> playing(const FifoCard &card, double t, double level);
    QString m_fifo;
    QTemporaryDir m_dir;
    DeviceModelPtr m_lra4;
};

void TestAudio::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_fifo = FifoCard::install(m_dir.path());
    QVERIFY(!m_fifo.isEmpty());
    m_lra4 = DeviceModelLibrary::builtin(QStringLiteral("lra4"));
}

std::unique_ptr<AudioTransport> TestAudio::playing(const FifoCard &card, double t, double level)
{
    auto transport = open(QStringLiteral("audio:semhaptest"));
    if (!transport)
        return nullptr;
    transport->setArmed(true);
    if (!playFor(card, 0.05))
        return nullptr;
    transport->send(frameOf(t, {level, level, level, level}));
    return playFor(card, 0.2) ? std::move(transport) : nullptr;
}

std::unique_ptr<AudioTransport> TestAudio::open(const QString &uri, const QString &model)
{
    QString error;
    std::unique_ptr<Transport> made =
        TransportFactory::create(uri, DeviceModelLibrary::builtin(model), &error);
    if (!made)
        qWarning("%s", qPrintable(error));
    auto transport = std::unique_ptr<AudioTransport>(dynamic_cast<AudioTransport *>(made.get()));
    if (transport)
        made.release();
    if (transport && !transport->open(&error))
        qWarning("%s", qPrintable(error));
    return transport;
}

void TestAudio::outputsAreListed()
{
    const std::vector<AudioOutputInfo> outputs = AudioSystem::list(0.0);
    const auto card = std::find_if(outputs.begin(), outputs.end(), [](const AudioOutputInfo &o) {
        return o.name == QLatin1String("semhaptest");
    });
    QVERIFY(card != outputs.end());
    QCOMPARE(card->channels, 128); // what PortAudio allows a plugin PCM
    QCOMPARE(card->sampleRate, Rate);
    QCOMPARE(card->hostApi, QStringLiteral("ALSA"));
    // The device manager offers each as a URI to bind.
    DeviceManager manager;
    const std::vector<PortInfo> present = manager.present();
    const auto port = std::find_if(present.begin(), present.end(), [](const PortInfo &p) {
        return p.uri == QLatin1String("audio:semhaptest");
    });
    QVERIFY(port != present.end());
    QCOMPARE(port->kind, QStringLiteral("audio"));
    QCOMPARE(port->outputChannels, 128);
    QCOMPARE(port->sampleRate, Rate);
}

void TestAudio::badAddressesAreRejected_data()
{
    QTest::addColumn<QString>("uri");
    QTest::addColumn<QString>("model");
    QTest::addColumn<QString>("errorPart");
    // Found out when the transport is made (the model).
    QTest::newRow("more channels than the model") << "audio:semhaptest?channels=1,2,3,4,5"
                                                  << "lra4"
                                                  << "5 output channels for the 4 channels";
    QTest::newRow("carriers not one per channel") << "audio:semhaptest?carrier=100,200"
                                                  << "lra4"
                                                  << "2 carriers for 4 channels";
    // Found out when it is opened (the card).
    QTest::newRow("channel beyond the card") << "audio:semhaptest?channels=1,129"
                                             << "fingertips2"
                                             << "has 128 output channels: there is no "
                                                "channel 129 for index";
    QTest::newRow("carrier above Nyquist") << "audio:semhaptest?carrier=22050"
                                           << "lra4"
                                           << "must be below 22050 Hz";
    QTest::newRow("no such output") << "audio:nosuchcard"
                                    << "lra4"
                                    << "no sound output 'nosuchcard'";
    QTest::newRow("two outputs match") << "audio:semhap"
                                       << "lra4"
                                       << "'semhap' names 2 sound outputs: semhaptest, "
                                          "semhapother";
}

void TestAudio::badAddressesAreRejected()
{
    QFETCH(QString, uri);
    QFETCH(QString, model);
    QFETCH(QString, errorPart);
    QString error;
    std::unique_ptr<Transport> transport =
        TransportFactory::create(uri, DeviceModelLibrary::builtin(model), &error);
    if (transport) {
        QVERIFY(!transport->open(&error));
        // The status says it too, for the Devices panel.
        QCOMPARE(transport->status().lastError, error);
        QCOMPARE(transport->status().state(), LinkState::Disconnected);
    }
    QVERIFY2(error.contains(errorPart), qPrintable(error));
}

void TestAudio::carrierAndEnvelope_data()
{
    QTest::addColumn<QString>("uri");
    QTest::addColumn<double>("value");
    QTest::addColumn<double>("gain");
    QTest::addColumn<double>("carrier");
    QTest::addColumn<double>("level");
    QTest::newRow("170 Hz by default") << "audio:semhaptest" << 0.5 << 1.0 << 170.0 << 0.5;
    QTest::newRow("full scale") << "audio:semhaptest" << 1.0 << 1.0 << 170.0 << 1.0;
    QTest::newRow("250 Hz") << "audio:semhaptest?carrier=250" << 0.8 << 1.0 << 250.0 << 0.8;
    QTest::newRow("per channel") << "audio:semhaptest?carrier=90,170,200,300" << 0.3 << 1.0 << 90.0
                                 << 0.3;
    QTest::newRow("gain") << "audio:semhaptest" << 0.8 << 0.5 << 170.0 << 0.4;
    QTest::newRow("clamped") << "audio:semhaptest" << 1.7 << 1.0 << 170.0 << 1.0;
    QTest::newRow("part of the name") << "audio:HAPTEST" << 0.6 << 1.0 << 170.0 << 0.6;
}

void TestAudio::carrierAndEnvelope()
{
    QFETCH(QString, uri);
    QFETCH(double, value);
    QFETCH(double, gain);
    QFETCH(double, carrier);
    QFETCH(double, level);
    FifoCard card(m_fifo, 4);
    auto transport = open(uri);
    QVERIFY(transport);
    transport->setArmed(true);
    transport->setGain(gain);
    QVERIFY(playFor(card, 0.05));
    transport->send(frameOf(1.0, {value, 0.0, 0.0, 0.0}));
    QVERIFY(playFor(card, 0.3));
    transport->close();
    QTRY_VERIFY(card.ended());

    const std::vector<float> steady = steadyPart(card.channel(0), level);
    QVERIFY(steady.size() > size_t(0.2 * Rate));
    QVERIFY2(std::abs(frequency(steady) - carrier) < 0.01 * carrier,
             qPrintable(QString::number(frequency(steady))));
    QVERIFY2(std::abs(peak(steady) - level) < 0.005, qPrintable(QString::number(peak(steady))));
    // What sent() says is what was played.
    const DeviceFrame played = [&] {
        std::vector<DeviceFrame> frames;
        std::uint64_t next = 0;
        transport->sent().readSince(&next, &frames);
        return frames.at(frames.size() - 2); // before the stop's rest frame
    }();
    QCOMPARE(played.t, 1.0);
    QCOMPARE(played.values[0], level);
    QCOMPARE(transport->sent().last().values[0], 0.0);
    const TransportStatus status = transport->status();
    QCOMPARE(status.framesSent, 2u);
    QVERIFY(status.latencyMs >= 0.0);
    QVERIFY(transport->latencyOf(0) >= 0.0);
}

void TestAudio::channelsGoWhereMapped()
{
    FifoCard card(m_fifo, 7);
    auto transport = open(QStringLiteral("audio:semhaptest?channels=4,2,7,1"));
    QVERIFY(transport);
    transport->setArmed(true);
    QVERIFY(playFor(card, 0.05));
    transport->send(frameOf(1.0, {0.2, 0.4, 0.6, 0.8}));
    QVERIFY(playFor(card, 0.3));
    transport->close();
    QTRY_VERIFY(card.ended());
    const int output[] = {4, 2, 7, 1};
    const double level[] = {0.2, 0.4, 0.6, 0.8};
    for (int c = 0; c < 4; ++c) {
        const std::vector<float> steady = steadyPart(card.channel(output[c] - 1), level[c]);
        QVERIFY2(std::abs(peak(steady) - level[c]) < 0.005, qPrintable(QString::number(c)));
    }
    for (const int silent : {3, 5, 6})
        QCOMPARE(peak(card.channel(silent - 1)), 0.0f);
}

void TestAudio::envelopeStepsAreRamped()
{
    FifoCard card(m_fifo, 2);
    auto transport = open(QStringLiteral("audio:semhaptest"), QStringLiteral("fingertips2"));
    QVERIFY(transport);
    transport->setArmed(true);
    QVERIFY(playFor(card, 0.05));
    // Steps between 0.2 and 0.9 at the model's rate (100 Hz): as a staircase, each would
    // jump the wave by up to 0.7. Each is sent once the card has taken the one before: sent
    // faster than a late callback takes them, the newest would win and skip a step.
    for (int k = 0; k < 40; ++k) {
        transport->send(frameOf(0.01 * k, {k % 2 ? 0.9 : 0.2, 0.0}));
        QTRY_COMPARE(transport->status().framesSent, std::uint32_t(k + 1));
    }
    QCOMPARE(transport->status().framesSkipped, 0u); // each step played
    // What the card got before the stop's fade (the FIFO holds what it has not read).
    const size_t beforeStop = card.frames();
    transport->close();
    QTRY_VERIFY(card.ended());
    std::vector<float> wave = card.channel(0);
    wave.resize(beforeStop);
    // A ramp spreads 0.7 over one update period (441 samples).
    const double largest = largestStep(wave, 0);
    QVERIFY2(largest <= smoothStep(0.9, 0.7 / 441.0), qPrintable(QString::number(largest)));
    QVERIFY(peak(wave) > 0.85f);                   // it did play the steps
    QCOMPARE(transport->status().framesSent, 41u); // and the stop's rest
}

void TestAudio::stopAllSilencesAtOnce()
{
    FifoCard card(m_fifo, 4);
    auto transport = playing(card, 2.0, 0.8);
    QVERIFY(transport);
    transport->stopAll();
    const size_t stoppedAt = card.frames();
    QVERIFY(playFor(card, 0.3));
    const std::vector<float> wave = card.channel(0);
    // Loud until the stop, and silent within a millisecond of a buffer after it.
    const auto lastLoud =
        std::find_if(wave.rbegin(), wave.rend(), [](float x) { return std::abs(x) > 0.0f; });
    const size_t end = size_t(wave.rend() - lastLoud);
    QVERIFY(end > 2000);
    QVERIFY2(end < stoppedAt + size_t(0.1 * Rate), qPrintable(QString::number(end - stoppedAt)));
    QVERIFY(wave.size() - end > size_t(0.15 * Rate));
    // Faded over 1 ms (44 samples), not cut.
    QVERIFY(largestStep(wave, end - size_t(0.01 * Rate)) <= smoothStep(0.8, 0.8 / 44.0));
    const DeviceFrame rest = transport->sent().last();
    QCOMPARE(rest.t, 2.0);
    QCOMPARE(rest.values[0], 0.0);
    transport->close();
}

void TestAudio::aValueSentAfterStopAllPlays()
{
    // Stop all drops what was waiting before it, not a value sent right after it: that one
    // is held (the transport does not send an unchanged value again) and must sound.
    FifoCard card(m_fifo, 4);
    auto transport = playing(card, 2.0, 0.8);
    QVERIFY(transport);
    transport->stopAll();
    transport->send(frameOf(2.1, {0.5, 0.5, 0.5, 0.5}));
    QVERIFY(playFor(card, 0.3));
    const std::vector<float> wave = card.channel(0);
    const std::vector<float> tail(wave.end() - qsizetype(0.05 * Rate), wave.end());
    QVERIFY2(std::abs(peak(tail) - 0.5f) < 0.01f, qPrintable(QString::number(peak(tail))));
    QCOMPARE(transport->sent().last().values[0], 0.5);
    transport->close();
}

void TestAudio::disarmingSilencesHeldValues()
{
    FifoCard card(m_fifo, 4);
    auto transport = open(QStringLiteral("audio:semhaptest"));
    QVERIFY(transport);
    QVERIFY(playFor(card, 0.05));
    // Disarmed, as real bands start: what is sent is not played.
    transport->send(frameOf(1.0, {0.7, 0.0, 0.0, 0.0}));
    QVERIFY(playFor(card, 0.2));
    QCOMPARE(peak(card.channel(0)), 0.0f);
    QCOMPARE(transport->sent().last().values[0], 0.0);
    // Armed, the values held since are played within a heartbeat, without a new send.
    transport->setArmed(true);
    QTRY_COMPARE(transport->sent().last().values[0], 0.7);
    QVERIFY(playFor(card, 0.2));
    QVERIFY(peak(card.channel(0)) > 0.69f);
    transport->setArmed(false);
    QTRY_COMPARE(transport->sent().last().values[0], 0.0);
    const size_t disarmedAt = card.frames();
    QVERIFY(playFor(card, 0.3));
    QCOMPARE(peak(card.channel(0, disarmedAt + size_t(0.2 * Rate))), 0.0f);
    transport->close();
}

void TestAudio::closeLeavesSilence()
{
    FifoCard card(m_fifo, 4);
    auto transport = playing(card, 1.0, 0.9);
    QVERIFY(transport);
    transport.reset(); // as on exit: the destructor closes
    QTRY_VERIFY(card.ended());
    // It played, and what the card got last is a fade to silence, not a cut.
    const std::vector<float> wave = card.channel(0);
    QVERIFY(peak(wave) > 0.85f);
    QCOMPARE(wave.back(), 0.0f);
    QVERIFY(largestStep(wave, wave.size() - size_t(0.02 * Rate)) <= smoothStep(0.9, 0.9 / 44.0));
}

void TestAudio::vanishedCardIsRetried()
{
    AudioSystem::list(0.0);
    auto card = std::make_unique<FifoCard>(m_fifo, 4);
    auto transport = open(QStringLiteral("audio:semhaptest"));
    QVERIFY(transport);
    transport->setArmed(true);
    transport->send(frameOf(1.0, {0.5, 0.0, 0.0, 0.0}));
    QVERIFY(playFor(*card, 0.1));
    card->stop(); // unplugged
    QTRY_COMPARE_WITH_TIMEOUT(transport->status().state(), LinkState::Disconnected, 3000);
    QVERIFY2(transport->status().lastError.contains(QStringLiteral("stopped playing")),
             qPrintable(transport->status().lastError));
    // The pipeline goes on: send() returns at once while the card is away.
    QElapsedTimer timer;
    timer.start();
    for (int k = 0; k < 100; ++k)
        transport->send(frameOf(2.0 + 0.002 * k, {0.5, 0.0, 0.0, 0.0}));
    QVERIFY(timer.elapsed() < 50);
    // Its next attempt waits in PortAudio for the card (the plugin's FIFO has no reader):
    // listing the outputs, as the Devices panel does every second, gives the last listing
    // rather than wait for it.
    QTest::qWait(1500);
    timer.restart();
    const std::vector<AudioOutputInfo> outputs = AudioSystem::list(0.0);
    QVERIFY2(timer.elapsed() < 200, qPrintable(QString::number(timer.elapsed())));
    QVERIFY(std::any_of(outputs.begin(), outputs.end(), [](const AudioOutputInfo &o) {
        return o.name == QLatin1String("semhaptest");
    }));
    // Plugged in again: the transport reopens it and plays what it holds.
    card = std::make_unique<FifoCard>(m_fifo, 4);
    QTRY_COMPARE_WITH_TIMEOUT(transport->status().state(), LinkState::Connected, 5000);
    QCOMPARE(transport->status().reconnects, 1u);
    QVERIFY(playFor(*card, 0.2));
    QVERIFY(std::abs(peak(card->channel(0)) - 0.5f) < 0.005f);
    transport->close();
}

void TestAudio::devicesCommandListsOutputs()
{
    QProcess semhap;
    semhap.start(QStringLiteral(SEMHAP_CLI_BINARY), {QStringLiteral("devices")});
    QVERIFY(semhap.waitForFinished(30000));
    QCOMPARE(semhap.exitCode(), 0);
    const QString out = QString::fromUtf8(semhap.readAllStandardOutput());
    QVERIFY2(out.contains(QStringLiteral("audio:DEVICE[?channels=")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral("  audio:semhaptest          128 ch, 44100 Hz (ALSA)\n")),
             qPrintable(out));
    QVERIFY(out.contains(QStringLiteral("  audio:semhapother ")));
    // Probing found no JACK server and said so to stderr, where the user would read it.
    QCOMPARE(QString::fromUtf8(semhap.readAllStandardError()), QString());
}

void TestAudio::playCommandPlaysOnTheCard()
{
    FifoCard card(m_fifo, 4);
    QProcess semhap;
    semhap.start(QStringLiteral(SEMHAP_CLI_BINARY),
                 {QStringLiteral("play"), QStringLiteral("vib.geiger"), QStringLiteral("--device"),
                  QStringLiteral("audio:semhaptest"), QStringLiteral("--intensity"),
                  QStringLiteral("0.5"), QStringLiteral("--duration"), QStringLiteral("1")});
    QVERIFY(semhap.waitForFinished(30000));
    QCOMPARE(semhap.exitCode(), 0);
    const QString out = QString::fromUtf8(semhap.readAllStandardOutput());
    QVERIFY2(out.startsWith(QStringLiteral("vib.geiger on audio:semhaptest: ")), qPrintable(out));
    QVERIFY2(out.contains(QStringLiteral(" ms\n")) && out.contains(QStringLiteral("latency")),
             qPrintable(out));
    QTRY_VERIFY(card.ended());
    // 25 ms pulses at 2 + 18 × 0.5 = 11 Hz for a second, the first at 0, on every output.
    for (int output = 0; output < 4; ++output) {
        const std::vector<float> wave = card.channel(output);
        int pulses = 0;
        size_t lastLoud = 0;
        for (size_t i = 0; i < wave.size(); ++i) {
            if (std::abs(wave[i]) < 0.5f)
                continue;
            if (pulses == 0 || i - lastLoud > size_t(0.02 * Rate))
                ++pulses;
            lastLoud = i;
        }
        QCOMPARE(pulses, 11);
        QVERIFY(peak(wave) > 0.95f);
    }
}

QTEST_GUILESS_MAIN(TestAudio)
#include "tst_audio.moc"
