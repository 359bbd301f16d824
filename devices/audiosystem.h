// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <mutex>
#include <vector>

namespace semhap {

/** A sound card output as `semhap devices` and the Devices panel list it. */
struct AudioOutputInfo
{
    QString name;            ///< PortAudio's device name: what `audio:NAME` matches
    QString hostApi;         ///< "ALSA", "JACK Audio Connection Kit", …
    int channels = 0;        ///< output channels
    double sampleRate = 0.0; ///< the device's default rate (Hz): what a stream runs at
    bool isDefault = false;  ///< the system's default output (`audio:default`)
    int index = -1;          ///< PortAudio's index, while the reference that listed it lives
};

/**
 * One reference on PortAudio, held while it lives: a stream's owner keeps one, a listing
 * takes one for a moment. PortAudio counts them and scans the sound cards when the first
 * is taken, so a card plugged in later is seen once no stream is open. Every call into
 * PortAudio outside its callback goes under lock(): it is not thread-safe. The libraries
 * under it (ALSA's probing, JACK's client) are kept from writing to stderr.
 */
class AudioSystem
{
public:
    AudioSystem();
    ~AudioSystem();
    AudioSystem(const AudioSystem &) = delete;
    AudioSystem &operator=(const AudioSystem &) = delete;

    /** False when PortAudio could not start (error() says why). */
    bool isOk() const { return m_ok; }
    QString error() const { return m_error; }
    /** The outputs present when PortAudio scanned them, in its order. */
    std::vector<AudioOutputInfo> outputs() const;
    /**
     * PortAudio's index of the output `name` names: `default`, an exact name, or a part of
     * one name (any case); -1 with a reason naming the candidates otherwise.
     */
    int find(const QString &name, QString *error) const;

    /** Held around every PortAudio call but the callback's. */
    static std::recursive_mutex &lock();
    /**
     * The outputs present, scanned at most every `maxAge` seconds: listing is probing every
     * card, too slow for a panel that polls each second. While another thread holds
     * PortAudio, the previous listing (empty before the first), so a caller on the GUI
     * thread never waits for a card.
     */
    static std::vector<AudioOutputInfo> list(double maxAge);

private:
    bool m_ok = false;
    QString m_error;
};

} // namespace semhap
