// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "routergraph.h"

#include <QJsonObject>

/**
 * A router whose activity tells routing from guessing: the right hand's force detector
 * feeds a grasp filter and a break filter; the break filter goes through a gate that opens
 * while the left hand's force detector has a grasp, then to a pattern on the right band.
 */
inline semhap::RouterGraph gatedRouter()
{
    using semhap::RouterNode;
    semhap::RouterGraph graph;
    graph.nodes = {
        {"force", "force", QJsonObject{{"gripper", "right"}}, {}},
        {"control", "force", QJsonObject{{"gripper", "left"}}, {}},
        {"grasps", "filter", QJsonObject{{"message", "grasp"}}, {}},
        {"breaks", "filter", QJsonObject{{"message", "break"}}, {}},
        {"gate", "gate", QJsonObject{{"mode", "open"}}, {}},
        {"buzz", "pattern", QJsonObject{{"pattern", "vib.geiger"}}, {}},
        {"right.vibro", "device", QJsonObject{{"model", "lra4"}, {"hand", "right"}}, {}},
    };
    graph.links = {{"force", "", "grasps", ""},  {"force", "", "breaks", ""},
                   {"breaks", "", "gate", "in"}, {"control", "", "gate", "control"},
                   {"gate", "", "buzz", ""},     {"buzz", "", "right.vibro", ""}};
    return graph;
}

/** A frame of `gripper` holding one object with `force` split over both fingertips. */
inline semhap::ContactFrame forceFrame(double t, semhap::Gripper gripper, double force)
{
    semhap::ContactFrame frame;
    frame.t = t;
    frame.gripper = gripper;
    frame.left.f = frame.right.f = force / 2;
    frame.left.n = frame.right.n = 16;
    frame.left.actor = frame.right.actor = 0;
    return frame;
}
