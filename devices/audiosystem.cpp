// SPDX-License-Identifier: MIT
#include "audiosystem.h"

#include "monotonic.h"

#include <QStringList>

#include <alsa/asoundlib.h>
#include <jack/jack.h>
#include <portaudio.h>

namespace semhap {

namespace {

void quietAlsa(const char *, int, const char *, int, const char *, ...) {}

void quietJack(const char *) {}

} // namespace

std::recursive_mutex &AudioSystem::lock()
{
    static std::recursive_mutex mutex;
    return mutex;
}

AudioSystem::AudioSystem()
{
    std::lock_guard<std::recursive_mutex> guard(lock());
    static bool quieted = false;
    if (!quieted) {
        // Probing prints dozens of lines for every PCM that has no card behind it (and
        // JACK's client one per attempt to reach a server): noise to a user, not news.
        snd_lib_error_set_handler(quietAlsa);
        jack_set_error_function(quietJack);
        jack_set_info_function(quietJack);
        quieted = true;
    }
    const PaError error = Pa_Initialize();
    m_ok = error == paNoError;
    if (!m_ok)
        m_error = QString::fromUtf8(Pa_GetErrorText(error));
}

AudioSystem::~AudioSystem()
{
    std::lock_guard<std::recursive_mutex> guard(lock());
    if (m_ok)
        Pa_Terminate();
}

std::vector<AudioOutputInfo> AudioSystem::outputs() const
{
    std::vector<AudioOutputInfo> out;
    if (!m_ok)
        return out;
    std::lock_guard<std::recursive_mutex> guard(lock());
    const PaDeviceIndex defaultOutput = Pa_GetDefaultOutputDevice();
    for (PaDeviceIndex i = 0; i < Pa_GetDeviceCount(); ++i) {
        const PaDeviceInfo *info = Pa_GetDeviceInfo(i);
        if (!info || info->maxOutputChannels <= 0)
            continue;
        const PaHostApiInfo *api = Pa_GetHostApiInfo(info->hostApi);
        out.push_back({QString::fromUtf8(info->name),
                       api ? QString::fromUtf8(api->name) : QString(), info->maxOutputChannels,
                       info->defaultSampleRate, i == defaultOutput, i});
    }
    return out;
}

int AudioSystem::find(const QString &name, QString *error) const
{
    if (!m_ok) {
        *error = QStringLiteral("PortAudio cannot start: %1").arg(m_error);
        return -1;
    }
    std::lock_guard<std::recursive_mutex> guard(lock());
    const std::vector<AudioOutputInfo> all = outputs();
    for (const AudioOutputInfo &output : all) {
        if (output.name == name)
            return output.index;
    }
    if (name == QLatin1String("default")) {
        if (Pa_GetDefaultOutputDevice() != paNoDevice)
            return Pa_GetDefaultOutputDevice();
        *error = QStringLiteral("there is no default sound output");
        return -1;
    }
    QStringList matches;
    int found = -1;
    for (const AudioOutputInfo &output : all) {
        if (output.name.contains(name, Qt::CaseInsensitive)) {
            matches.append(output.name);
            found = output.index;
        }
    }
    if (matches.size() == 1)
        return found;
    if (matches.isEmpty())
        *error = all.empty() ? QStringLiteral("no sound output '%1': there are no sound "
                                              "outputs")
                                   .arg(name)
                             : QStringLiteral("no sound output '%1' (`semhap devices` lists "
                                              "them)")
                                   .arg(name);
    else
        *error = QStringLiteral("'%1' names %2 sound outputs: %3")
                     .arg(name)
                     .arg(matches.size())
                     .arg(matches.join(QStringLiteral(", ")));
    return -1;
}

std::vector<AudioOutputInfo> AudioSystem::list(double maxAge)
{
    static std::mutex cacheMutex;
    static std::vector<AudioOutputInfo> cached;
    static double scanned = -1.0;
    std::lock_guard<std::mutex> cacheLock(cacheMutex);
    const double now = monotonicSeconds();
    if (scanned >= 0.0 && now - scanned < maxAge)
        return cached;
    // A stream being opened (a card that takes its time) holds PortAudio: the last
    // listing will do (none before the first), rather than a panel that waits.
    const std::unique_lock<std::recursive_mutex> guard(lock(), std::try_to_lock);
    if (!guard.owns_lock())
        return cached;
    const AudioSystem system;
    cached = system.outputs();
    scanned = now;
    return cached;
}

} // namespace semhap
