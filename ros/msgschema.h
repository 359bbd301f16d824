// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace semhap {

/**
 * A ROS 2 message type as its `.msg` text defines it, with the types it uses: the `ros2msg`
 * schema encoding of MCAP and of the Foxglove WebSocket protocol. The text is the type's own
 * fields, then each type it uses after a line of `=` and a line `MSG: package/Type`, as
 * rosbag2 and foxglove_bridge write it. Constants and default values are read past; field
 * layout is what the CDR decoder needs.
 */
class MsgSchema
{
public:
    /** The built-in types; `Complex` is a field of another message type. */
    enum class Primitive : std::uint8_t
    {
        Bool,
        Byte,
        Char,
        Int8,
        UInt8,
        Int16,
        UInt16,
        Int32,
        UInt32,
        Int64,
        UInt64,
        Float32,
        Float64,
        String,
        WString,
        Complex,
    };

    struct Field
    {
        QString name;
        Primitive primitive = Primitive::Complex;
        int type = -1;           ///< with Complex: the index into types()
        bool array = false;      ///< an array: fixed (size > 0) or a sequence (size 0)
        std::uint32_t size = 0;  ///< a fixed array's length
        std::uint32_t bound = 0; ///< a bounded sequence's or string's largest length, or 0
    };

    struct Type
    {
        QString name; ///< package/Type, without the "msg/" part
        std::vector<Field> fields;
    };

    /** The most nested a type may be, so that a hostile schema costs bounded work. */
    static constexpr int MaxDepth = 32;

    /**
     * Parses the schema of type `name` (e.g. geometry_msgs/msg/WrenchStamped) from `text`.
     * On an error, false and `error` as `LINE:COL: reason`, the line counted in `text`.
     */
    static bool parse(const QString &name, const QByteArray &text, MsgSchema *schema,
                      QString *error);

    /** The types, the message's own first. */
    const std::vector<Type> &types() const { return m_types; }
    const Type &root() const { return m_types.front(); }

    /** A type's field, by name, or nullptr. */
    static const Field *field(const Type &type, const QString &name);
    /** Whether `name` is a built-in type (int32, string, …) rather than a message type. */
    static bool isBuiltin(const QString &name);
    /** Whether a field's primitive is a number (bool, byte and char included). */
    static bool isNumber(Primitive primitive);
    /** A field's type as the .msg text writes it, for messages: `float64[3]`, `Vector3`. */
    QString typeName(const Field &field) const;

private:
    std::vector<Type> m_types;
};

} // namespace semhap
