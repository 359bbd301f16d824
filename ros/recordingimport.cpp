// SPDX-License-Identifier: MIT
#include "recordingimport.h"

#include "pipeline.h"
#include "recordingreader.h"
#include "router.h"
#include "sessionwriter.h"

#include <cmath>

namespace semhap {

bool RecordingImport::run(const QString &recording, const QString &topics,
                          std::unique_ptr<Router> router, SessionInfo info, const QString &session,
                          const std::function<bool(double done)> &keepGoing, Result *result)
{
    *result = Result();
    TopicMap map;
    LoadError loadError;
    if (!TopicMap::load(topics, &map, &loadError)) {
        result->error = loadError.toString();
        return false;
    }
    RecordingReader reader(recording, map, topics);
    if (!reader.open()) {
        result->error = reader.error();
        return false;
    }
    info.source = QStringLiteral("import");
    info.extra.insert(QStringLiteral("recording"), recording);
    info.extra.insert(QStringLiteral("topics"), topics);
    SessionWriter::Options options;
    options.waitWhenFull = true; // a file keeps no clock: nothing may be dropped
    options.steadyClock = false; // nor were its frames made now
    std::unique_ptr<SessionWriter> writer =
        SessionWriter::create(session, info, *router, options, &result->error);
    if (!writer)
        return false;
    writer->setActorTable(&reader.actors());

    Pipeline pipeline(std::move(router));
    ContactFrame frame;
    while (reader.next(&frame)) {
        writer->recordContactFrame(frame, std::nan(""));
        pipeline.process(frame, *writer);
        // Asked every 4096 frames: a few times a second at any speed worth showing.
        if ((++result->frames & 4095) == 0 && keepGoing && !keepGoing(reader.progress())) {
            result->cancelled = true;
            break;
        }
    }
    if (result->frames > 0)
        pipeline.flush(*writer);
    result->startTime = reader.startTime();
    if (!writer->finish(&result->error))
        return false;
    if (!reader.error().isEmpty()) {
        result->error = reader.error(); // the file changed since it was checked
        return false;
    }
    if (keepGoing && !result->cancelled)
        keepGoing(1.0);
    return true;
}

} // namespace semhap
