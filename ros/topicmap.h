// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "loaderror.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <array>
#include <vector>

namespace semhap {

class JsonReader;

/**
 * How a robot's topics become contact frames: a `semhap.topics/1` file (docs/ros.md). Per
 * gripper, each fingertip's force topic and the path of the force vector in its messages,
 * the axis along which its sensor feels the grip, the force at which it is in contact, and
 * optionally a tactile count; the topic whose messages make the frames; named signals.
 */
struct TopicMap
{
    /** Which time a message has: its `header.stamp`, or when it was logged (or arrived). */
    enum class Time
    {
        Header,
        Log
    };

    /** A sensor axis, and the rotation that turns it into the gripper frame's +y. */
    enum class Axis
    {
        PlusX,
        MinusX,
        PlusY,
        MinusY,
        PlusZ,
        MinusZ
    };

    /** A number from a topic: the topic and the path of the field in its messages. */
    struct Source
    {
        QString topic;
        QString field;
    };

    struct Tip
    {
        bool present = false;
        QString topic;
        QString force = QStringLiteral("wrench.force"); ///< the path of (x, y, z)
        Axis normalAxis = Axis::PlusY;
        double contactThreshold = 0.5; ///< N: at or above it, the tip touches `actor`
        QString actor = QStringLiteral("object");
        double mu = 0.0; ///< friction coefficient to put in the frames; 0: unknown
        bool hasCount = false;
        Source count; ///< the tip's number of contacts, from a tactile sensor
    };

    struct Signal
    {
        QString name;
        Source source;
    };

    struct GripperTopics
    {
        bool present = false;
        /// A gripper a recording may lack (the built-in map's, for one-handed sessions):
        /// its topics may be missing, and then it makes no frames.
        bool optional = false;
        QString clock; ///< the topic whose messages make frames; default: the left tip's
        Tip left;
        Tip right;
        std::vector<Signal> signalList;
    };

    Time time = Time::Header;
    std::array<GripperTopics, 2> grippers; ///< by Gripper

    /**
     * Reads a map file, or the built-in map `semhap` of semhap's own exports
     * (McapExport::topicMap()); false with `FILE: /pointer: reason` in `error`.
     */
    static bool load(const QString &path, TopicMap *map, LoadError *error);
    /** Reads a map from its JSON (pointer errors through `reader`). */
    static bool fromJson(JsonReader &reader, const QJsonObject &json, TopicMap *map);

    /** Every topic the map reads, once each, in the map's order. */
    QStringList topics() const;
    /** `force` turned so that the sensor's `axis` becomes +y (docs/ros.md's table). */
    static std::array<double, 3> rotate(Axis axis, const std::array<double, 3> &force);
};

} // namespace semhap
