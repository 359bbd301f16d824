// SPDX-License-Identifier: MIT
#include "gripperadapter.h"

#include "jsonreader.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>

#include <cmath>

namespace semhap {

namespace {

/** A JSON array of `n` finite numbers at `key`. */
template<size_t N>
bool numbers(JsonReader &reader, const QJsonObject &object, const QString &pointer,
             QLatin1String key, std::array<double, N> *out)
{
    QJsonArray array;
    if (!object.contains(key))
        return true;
    if (!reader.array(object, pointer, key, &array))
        return false;
    const QString at = pointer + QLatin1Char('/') + key;
    if (array.size() != int(N))
        return reader.fail(
            at, QStringLiteral("must have %1 numbers, has %2").arg(N).arg(array.size()));
    for (size_t i = 0; i < N; ++i) {
        if (!reader.finiteNumber(array[int(i)], jsonPointerChild(at, int(i)), &(*out)[i]))
            return false;
    }
    return true;
}

bool readFinger(JsonReader &reader, const QJsonObject &fingers, QLatin1String side,
                GripperAdapter::Finger *finger)
{
    const QString pointer = QStringLiteral("/fingers/") + side;
    QJsonObject json;
    if (!reader.object(fingers, QStringLiteral("/fingers"), side, &json) ||
        !reader.checkKeys(json, pointer, {QLatin1String("joint"), QLatin1String("pads")}) ||
        !reader.nonEmptyString(json, pointer, QLatin1String("joint"), &finger->joint) ||
        !reader.strings(json, pointer, QLatin1String("pads"), &finger->pads))
        return false;
    if (finger->pads.isEmpty())
        return reader.fail(pointer + QStringLiteral("/pads"),
                           QStringLiteral("must name at least one body or geom"));
    return true;
}

} // namespace

bool GripperAdapter::read(const QString &path, GripperAdapter *out, LoadError *error)
{
    QJsonObject json;
    if (!readJsonObjectFile(path, &json, error) ||
        !checkFormat(json, path, QLatin1String(Format), error))
        return false;
    JsonReader reader(path);
    GripperAdapter a;
    a.file = path;
    QJsonObject mount, fingers, force, detectors;
    QString closing;
    QString collisions = QStringLiteral("all");
    double fullContacts = 0.0;
    const bool ok =
        reader.checkKeys(json, QString(),
                         {QLatin1String("format"), QLatin1String("name"), QLatin1String("model"),
                          QLatin1String("root"), QLatin1String("mount"), QLatin1String("fingers"),
                          QLatin1String("closing"), QLatin1String("force"),
                          QLatin1String("detectors"), QLatin1String("collisions")}) &&
        reader.nonEmptyString(json, QString(), QLatin1String("name"), &a.name) &&
        reader.nonEmptyString(json, QString(), QLatin1String("model"), &a.modelName) &&
        reader.nonEmptyString(json, QString(), QLatin1String("root"), &a.root) &&
        reader.object(json, QString(), QLatin1String("mount"), &mount, false) &&
        reader.checkKeys(mount, QStringLiteral("/mount"),
                         {QLatin1String("pos"), QLatin1String("quat")}) &&
        numbers(reader, mount, QStringLiteral("/mount"), QLatin1String("pos"), &a.mountPos) &&
        numbers(reader, mount, QStringLiteral("/mount"), QLatin1String("quat"), &a.mountQuat) &&
        reader.object(json, QString(), QLatin1String("fingers"), &fingers) &&
        reader.checkKeys(fingers, QStringLiteral("/fingers"),
                         {QLatin1String("left"), QLatin1String("right")}) &&
        readFinger(reader, fingers, QLatin1String("left"), &a.fingers[0]) &&
        readFinger(reader, fingers, QLatin1String("right"), &a.fingers[1]) &&
        reader.string(json, QString(), QLatin1String("closing"), &closing) &&
        reader.string(json, QString(), QLatin1String("collisions"), &collisions, false) &&
        reader.object(json, QString(), QLatin1String("force"), &force, false) &&
        reader.checkKeys(
            force, QStringLiteral("/force"),
            {QLatin1String("max"), QLatin1String("open"), QLatin1String("damping")}) &&
        reader.number(force, QStringLiteral("/force"), QLatin1String("max"), &a.maxForce, false) &&
        reader.number(force, QStringLiteral("/force"), QLatin1String("open"), &a.openForce,
                      false) &&
        reader.number(force, QStringLiteral("/force"), QLatin1String("damping"), &a.damping,
                      false) &&
        reader.object(json, QString(), QLatin1String("detectors"), &detectors, false) &&
        reader.checkKeys(detectors, QStringLiteral("/detectors"),
                         {QLatin1String("fullContacts"), QLatin1String("forceRipple")}) &&
        reader.number(detectors, QStringLiteral("/detectors"), QLatin1String("fullContacts"),
                      &fullContacts, false) &&
        reader.number(detectors, QStringLiteral("/detectors"), QLatin1String("forceRipple"),
                      &a.forceRipple, false);
    if (ok) {
        a.hasMount = json.contains(QLatin1String("mount"));
        const double norm =
            std::sqrt(a.mountQuat[0] * a.mountQuat[0] + a.mountQuat[1] * a.mountQuat[1] +
                      a.mountQuat[2] * a.mountQuat[2] + a.mountQuat[3] * a.mountQuat[3]);
        if (norm < 1e-9)
            reader.fail(QStringLiteral("/mount/quat"), QStringLiteral("must not be all zeros"));
        else
            for (double &q : a.mountQuat)
                q /= norm;
        if (closing == QLatin1String("positive"))
            a.closing = 1;
        else if (closing == QLatin1String("negative"))
            a.closing = -1;
        else
            reader.fail(QStringLiteral("/closing"),
                        QStringLiteral("must be 'positive' or 'negative' (the direction of the "
                                       "fingers' joints that closes them), got %1")
                            .arg(quoted(closing)));
        if (collisions == QLatin1String("pads"))
            a.padsOnly = true;
        else if (collisions != QLatin1String("all"))
            reader.fail(QStringLiteral("/collisions"),
                        QStringLiteral("must be 'all' (every geom of the model collides, as it "
                                       "says) or 'pads' (only the pads), got %1")
                            .arg(quoted(collisions)));
        if (!(a.maxForce > 0 && a.maxForce <= 10000))
            reader.fail(QStringLiteral("/force/max"),
                        QStringLiteral("must be above 0 and at most 10000 N"));
        if (!(a.openForce > 0 && a.openForce <= a.maxForce))
            reader.fail(QStringLiteral("/force/open"),
                        QStringLiteral("must be above 0 and at most /force/max"));
        if (!(a.damping >= 0 && a.damping <= 10000))
            reader.fail(QStringLiteral("/force/damping"),
                        QStringLiteral("must be from 0 to 10000 N s/m"));
        if (detectors.contains(QLatin1String("fullContacts")) &&
            !(fullContacts >= 1 && fullContacts <= 1000 &&
              fullContacts == std::floor(fullContacts)))
            reader.fail(QStringLiteral("/detectors/fullContacts"),
                        QStringLiteral("must be a whole number from 1 to 1000"));
        a.fullContacts = int(fullContacts);
        if (detectors.contains(QLatin1String("forceRipple")) &&
            !(a.forceRipple >= 0 && a.forceRipple <= 1000))
            reader.fail(QStringLiteral("/detectors/forceRipple"),
                        QStringLiteral("must be from 0 to 1000 N"));
        if (a.fingers[0].joint == a.fingers[1].joint)
            reader.fail(QStringLiteral("/fingers/right/joint"),
                        QStringLiteral("must differ from the left finger's"));
        a.model = QDir::cleanPath(QFileInfo(path).absoluteDir().filePath(a.modelName));
    }
    if (reader.error().isSet()) {
        *error = reader.error();
        return false;
    }
    *out = a;
    return true;
}

} // namespace semhap
