// SPDX-License-Identifier: MIT
#pragma once

#include "contactframe.h"
#include "nametable.h"

#include <QString>

namespace semhap {

/**
 * The kind of detector that produced an event: the type of its router node. The four built
 * in are named here; a detector type added to the node-type table (routerNodeTypes()) gets
 * the next id, and its name is its type's.
 */
enum class DetectorKind : int
{
    Force,
    Slip,
    Threshold,
    Compose
};
/**
 * A semantic message: its id in messageNames(). grasp (a confirmation), break and slip
 * (exceptions) are built in; a router's threshold and compose nodes may name new ones, whose
 * ids follow (a new message's category is its node's).
 */
enum class Message : int
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

/** The kind's name (its node type's); defined with the node-type table. */
QString detectorKindName(DetectorKind kind);
QString messageName(Message message);
QString categoryName(Category category);
QString eventPhaseName(EventPhase phase);
bool detectorKindFromName(const QString &name, DetectorKind *kind);
/**
 * A built-in message, or a new one of the form `[a-z0-9_.]+` (interned); false for any other
 * name, or when messageNames() is full.
 */
bool messageFromName(const QString &name, Message *message);
/** Whether `message` is grasp, break or slip. */
bool isBuiltinMessage(Message message);
/** The table of message names: grasp, break and slip at 0..2, then the new ones. */
NameTable &messageNames();
bool categoryFromName(const QString &name, Category *category);
bool eventPhaseFromName(const QString &name, EventPhase *phase);
/** The category of a built-in message; a new message's is its node's. */
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
