// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"

#include <QString>

namespace semhap {

/** The kind of detector that produced an event. */
enum class DetectorKind
{
    Force,
    Slip,
    Threshold
};
/** A semantic message. grasp is a confirmation; break and slip are exceptions. */
enum class Message
{
    Grasp,
    Break,
    Slip
};
enum class Category
{
    Confirmation,
    Exception
};
enum class EventPhase
{
    Begin,
    Update,
    End
};

QString detectorKindName(DetectorKind kind);
QString messageName(Message message);
QString categoryName(Category category);
QString eventPhaseName(EventPhase phase);
bool detectorKindFromName(const QString &name, DetectorKind *kind);
bool messageFromName(const QString &name, Message *message);
bool categoryFromName(const QString &name, Category *category);
bool eventPhaseFromName(const QString &name, EventPhase *phase);
/** The category a message belongs to. */
Category categoryOf(Message message);

/**
 * One lifecycle step of a semantic message (spec section 1). `node` indexes the router's
 * node table (the detector's id); names are resolved only when the event is written.
 */
struct SemanticEvent
{
    double t = 0.0;
    Gripper gripper = Gripper::Right;
    int node = -1;
    DetectorKind detector = DetectorKind::Force;
    Message message = Message::Grasp;
    Category category = Category::Confirmation;
    EventPhase phase = EventPhase::Begin;
    double intensity = 1.0; ///< in [0, 1]; on end, the last value
};

} // namespace semhap
