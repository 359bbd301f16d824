// SPDX-License-Identifier: MIT
#pragma once

#include "devicemodel.h"
#include "hapticconverter.h"
#include "hjifdocument.h"
#include "semanticevent.h"

namespace semhap {

class Router;

/**
 * Converts between semhap patterns and routers and MPEG haptics files (HJIF, ISO/IEC
 * 23090-31): a band's model becomes a perception with its reference device and a channel per
 * actuator; each channel's rendered envelope becomes keyframes, in a Curve band for a device
 * that takes levels (bellows) and in a VectorialWave band on the carrier of one that makes its
 * own (an LRA). A router's messages become an effect library with semantic keywords. What
 * does not map is listed as warnings (docs/convert.md).
 */
class HjifConverter
{
public:
    /** Reads an HJIF file as a semhap pattern document (not yet parsed). */
    static bool readPattern(const QString &path, const ConvertOptions &options,
                            QJsonObject *pattern, QStringList *warnings, LoadError *error);
    /** The same from bytes; `file` names the input in messages. */
    static bool parsePattern(const QByteArray &bytes, const QString &file,
                             const ConvertOptions &options, QJsonObject *pattern,
                             QStringList *warnings, LoadError *error);
    /** A pattern from a document read already. */
    static bool documentToPattern(const HjifDocument &document, const QString &file,
                                  const ConvertOptions &options, QJsonObject *pattern,
                                  QStringList *warnings, LoadError *error);

    /** The HJIF document of a pattern, rendered as `HapticConverter` renders for export. */
    static bool patternToDocument(const QJsonObject &pattern, const QString &file,
                                  const ConvertOptions &options, HjifDocument *document,
                                  QStringList *warnings, LoadError *error);
    /**
     * The HJIF document of a router: a perception per band that plays a message, whose
     * effect library holds each message's pattern (a library effect per distinct channel
     * envelope, with the message's semantic keywords), and whose channels play the messages
     * in turn, Gap apart, by reference.
     */
    static bool routerToDocument(const Router &router, const QString &file,
                                 const ConvertOptions &options, HjifDocument *document,
                                 QStringList *warnings, LoadError *error);
    /** Writes a pattern as an HJIF file (the designer's Export). */
    static bool writePattern(const QJsonObject &pattern, const QString &path,
                             const ConvertOptions &options, QStringList *warnings,
                             LoadError *error);
    /** The bytes of a document as written. */
    static QByteArray serialize(const HjifDocument &document);

    /**
     * The term of the standard's effect-semantic scheme for a message: confirmation
     * `UX/Confirmation`; break and slip, which warn, `UX/Alarm` (the scheme has no warning).
     */
    static QString semanticKeyword(Message message, Category category);
    /** The semhap modality of an HJIF perception modality; empty for those semhap lacks. */
    static QString modalityOf(const QString &perceptionModality);

    /** The scheme of semantic keywords written (the standard's default). */
    static constexpr const char *SemanticScheme = "urn:mpeg:mpegi:haptics:effectsemantic:2023";
    /** Seconds between two messages' patterns on a router's timeline. */
    static constexpr double Gap = 1.0;
    /** Ticks per second written: the render's 1 kHz, and the Simple Parametric profile's. */
    static constexpr qint64 Timescale = 1000;
};

} // namespace semhap
