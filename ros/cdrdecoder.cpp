// SPDX-License-Identifier: MIT
#include "cdrdecoder.h"

#include <QRegularExpression>
#include <QtEndian>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace semhap {

namespace {

using Primitive = MsgSchema::Primitive;

/** The bytes of one value of a primitive in CDR (a string's length word alone). */
std::size_t sizeOf(Primitive primitive)
{
    switch (primitive) {
    case Primitive::Bool:
    case Primitive::Byte:
    case Primitive::Char:
    case Primitive::Int8:
    case Primitive::UInt8:
        return 1;
    case Primitive::Int16:
    case Primitive::UInt16:
        return 2;
    case Primitive::Int32:
    case Primitive::UInt32:
    case Primitive::Float32:
    case Primitive::String:
    case Primitive::WString:
        return 4;
    case Primitive::Int64:
    case Primitive::UInt64:
    case Primitive::Float64:
        return 8;
    case Primitive::Complex:
        break;
    }
    return 0;
}

/** Elements that take no bytes may not repeat without end: a hostile count costs bounded time. */
constexpr std::uint64_t MaxEmptyElements = 1 << 16;

QString fieldList(const MsgSchema::Type &type)
{
    QStringList names;
    for (const MsgSchema::Field &f : type.fields)
        names << f.name;
    return names.isEmpty() ? QStringLiteral("none") : names.join(QStringLiteral(", "));
}

} // namespace

struct CdrDecoder::Cursor
{
    const char *base; ///< the first byte after the encapsulation header
    std::size_t size;
    std::size_t pos = 0;
    bool little = true;
    QString why;

    bool fail(const QString &reason)
    {
        if (why.isEmpty())
            why = QStringLiteral("byte %1: %2").arg(pos + 4).arg(reason);
        return false;
    }
    bool align(std::size_t n)
    {
        const std::size_t aligned = (pos + n - 1) & ~(n - 1);
        if (aligned > size)
            return fail(QStringLiteral("the message ends early"));
        pos = aligned;
        return true;
    }
    bool need(std::uint64_t n)
    {
        if (n > size - pos)
            return fail(QStringLiteral("the message ends early"));
        return true;
    }
    template<typename T> bool read(T *value)
    {
        if (!align(sizeof(T)) || !need(sizeof(T)))
            return false;
        *value = little ? qFromLittleEndian<T>(base + pos) : qFromBigEndian<T>(base + pos);
        pos += sizeof(T);
        return true;
    }
    bool number(Primitive primitive, double *value)
    {
        switch (primitive) {
        case Primitive::Bool:
        case Primitive::Byte:
        case Primitive::Char:
        case Primitive::UInt8: {
            std::uint8_t v = 0;
            return read(&v) && (*value = v, true);
        }
        case Primitive::Int8: {
            std::int8_t v = 0;
            return read(&v) && (*value = v, true);
        }
        case Primitive::Int16: {
            std::int16_t v = 0;
            return read(&v) && (*value = v, true);
        }
        case Primitive::UInt16: {
            std::uint16_t v = 0;
            return read(&v) && (*value = v, true);
        }
        case Primitive::Int32: {
            std::int32_t v = 0;
            return read(&v) && (*value = v, true);
        }
        case Primitive::UInt32: {
            std::uint32_t v = 0;
            return read(&v) && (*value = v, true);
        }
        case Primitive::Int64: {
            std::int64_t v = 0;
            return read(&v) && (*value = double(v), true);
        }
        case Primitive::UInt64: {
            std::uint64_t v = 0;
            return read(&v) && (*value = double(v), true);
        }
        case Primitive::Float32: {
            std::uint32_t bits = 0;
            float v = 0;
            if (!read(&bits))
                return false;
            std::memcpy(&v, &bits, sizeof v);
            *value = double(v);
            return true;
        }
        case Primitive::Float64: {
            std::uint64_t bits = 0;
            if (!read(&bits))
                return false;
            std::memcpy(value, &bits, sizeof *value);
            return true;
        }
        default:
            return fail(QStringLiteral("not a number"));
        }
    }
};

bool CdrDecoder::compile(const MsgSchema &schema, const QStringList &paths, CdrDecoder *decoder,
                         QString *error)
{
    static const QRegularExpression part(
        QStringLiteral("^([A-Za-z][A-Za-z0-9_]*)(?:\\[([0-9]{1,9})\\])?$"));
    CdrDecoder d;
    d.m_schema = schema;
    d.m_nodes.emplace_back();
    const std::vector<MsgSchema::Type> &types = schema.types();
    int leafCount = 0;
    // The take of (field, element) in a node, made on first use.
    const auto takeOf = [&](int node, int field, int element) -> Take & {
        for (Take &t : d.m_nodes[size_t(node)].takes) {
            if (t.field == field && t.element == element)
                return t;
        }
        d.m_nodes[size_t(node)].takes.push_back({field, element, -1, -1});
        return d.m_nodes[size_t(node)].takes.back();
    };
    for (const QString &text : paths) {
        const auto fail = [&](const QString &reason) {
            *error = QStringLiteral("'%1': %2").arg(text, reason);
            return false;
        };
        Path path;
        path.offset = d.m_valueCount;
        int type = 0;
        int node = 0;
        const QStringList parts = text.split(QLatin1Char('.'));
        for (int k = 0; k < parts.size(); ++k) {
            const QRegularExpressionMatch match = part.match(parts[k]);
            if (!match.hasMatch())
                return fail(
                    QStringLiteral("'%1' is not a field name or NAME[INDEX]").arg(parts[k]));
            const MsgSchema::Type &owner = types[size_t(type)];
            const QString name = match.captured(1);
            const MsgSchema::Field *field = MsgSchema::field(owner, name);
            if (!field)
                return fail(QStringLiteral("%1 has no field '%2'; its fields: %3")
                                .arg(owner.name, name, fieldList(owner)));
            const int index = int(field - owner.fields.data());
            const int element = match.captured(2).isEmpty() ? -1 : match.captured(2).toInt();
            const QString kind = schema.typeName(*field);
            if (field->array && element < 0)
                return fail(QStringLiteral("'%1' is an array (%2): pick an element, as %1[0]")
                                .arg(name, kind));
            if (!field->array && element >= 0)
                return fail(QStringLiteral("'%1' is not an array (%2)").arg(name, kind));
            if (field->array && field->size > 0 && std::uint32_t(element) >= field->size)
                return fail(QStringLiteral("'%1' has %2 elements").arg(name).arg(field->size));
            const bool last = k == parts.size() - 1;
            if (MsgSchema::isNumber(field->primitive)) {
                if (!last)
                    return fail(
                        QStringLiteral("'%1' is a number (%2), with no fields").arg(name, kind));
                Take &take = takeOf(node, index, element);
                if (take.slot < 0)
                    take.slot = leafCount++;
                path.leaves.push_back(take.slot);
                break;
            }
            if (field->primitive != Primitive::Complex)
                return fail(QStringLiteral("'%1' is a %2, not a number").arg(name, kind));
            Take *take = &takeOf(node, index, element);
            if (take->node < 0) {
                take->node = int(d.m_nodes.size());
                d.m_nodes.emplace_back(); // may move the takes: `take` is not used after
            }
            node = takeOf(node, index, element).node;
            type = field->type;
            if (!last)
                continue;
            // A message of numbers alone (a Vector3, a time) gives them in order.
            const MsgSchema::Type &inner = types[size_t(type)];
            for (int f = 0; f < int(inner.fields.size()); ++f) {
                const MsgSchema::Field &leaf = inner.fields[size_t(f)];
                if (!MsgSchema::isNumber(leaf.primitive) || leaf.array)
                    return fail(QStringLiteral("'%1' is %2, not a number or a message of "
                                               "numbers; its fields: %3")
                                    .arg(name, inner.name, fieldList(inner)));
                Take &leafTake = takeOf(node, f, -1);
                if (leafTake.slot < 0)
                    leafTake.slot = leafCount++;
                path.leaves.push_back(leafTake.slot);
            }
            if (inner.fields.empty())
                return fail(
                    QStringLiteral("'%1' is %2, which has no fields").arg(name, inner.name));
            path.time = inner.fields.size() == 2 && inner.fields[0].name == QLatin1String("sec") &&
                        inner.fields[1].name == QLatin1String("nanosec");
        }
        path.width = path.time ? 1 : int(path.leaves.size());
        d.m_valueCount += path.width;
        d.m_paths.push_back(path);
    }
    d.m_leaves.assign(size_t(leafCount), 0.0);

    // The fewest bytes one of each type takes, to bound a sequence's count by the bytes left.
    d.m_minSize.assign(types.size(), -1);
    std::function<std::uint64_t(int)> minSize = [&](int type) -> std::uint64_t {
        if (d.m_minSize[size_t(type)] >= 0)
            return std::uint64_t(d.m_minSize[size_t(type)]);
        std::uint64_t total = 0;
        for (const MsgSchema::Field &f : types[size_t(type)].fields) {
            std::uint64_t one =
                f.primitive == Primitive::Complex ? minSize(f.type) : sizeOf(f.primitive);
            if (f.array)
                one = f.size > 0 ? one * f.size : 4;
            total = std::min<std::uint64_t>(total + one, std::numeric_limits<int>::max());
        }
        d.m_minSize[size_t(type)] = int(total);
        return total;
    };
    minSize(0);
    for (size_t t = 0; t < types.size(); ++t)
        minSize(int(t));
    *decoder = std::move(d);
    return true;
}

bool CdrDecoder::decode(const char *data, std::size_t size, double *values, QString *error)
{
    if (size < 4 || data[0] != 0 || (data[1] != 0 && data[1] != 1)) {
        *error = size < 4 ? QStringLiteral("byte 0: no CDR encapsulation header")
                          : QStringLiteral("byte 0: encapsulation 0x%1%2 is not plain CDR")
                                .arg(std::uint8_t(data[0]), 2, 16, QLatin1Char('0'))
                                .arg(std::uint8_t(data[1]), 2, 16, QLatin1Char('0'));
        return false;
    }
    Cursor at{data + 4, size - 4, 0, data[1] == 1, QString()};
    std::fill(m_leaves.begin(), m_leaves.end(), std::numeric_limits<double>::quiet_NaN());
    if (!walk(at, 0, 0)) {
        *error = at.why;
        return false;
    }
    for (const Path &p : m_paths) {
        if (p.time) {
            values[p.offset] = (m_leaves[size_t(p.leaves[0])] - double(m_epoch)) +
                               m_leaves[size_t(p.leaves[1])] * 1e-9;
            continue;
        }
        for (size_t i = 0; i < p.leaves.size(); ++i)
            values[size_t(p.offset) + i] = m_leaves[size_t(p.leaves[i])];
    }
    return true;
}

bool CdrDecoder::walk(Cursor &at, int type, int node)
{
    const std::vector<MsgSchema::Field> &fields = m_schema.types()[size_t(type)].fields;
    const std::vector<Take> *takes = node >= 0 ? &m_nodes[size_t(node)].takes : nullptr;
    const auto takeOf = [&](int field, int element) -> const Take * {
        if (takes) {
            for (const Take &t : *takes) {
                if (t.field == field && t.element == element)
                    return &t;
            }
        }
        return nullptr;
    };
    for (int f = 0; f < int(fields.size()); ++f) {
        const MsgSchema::Field &field = fields[size_t(f)];
        if (!field.array) {
            if (!value(at, field, takeOf(f, -1)))
                return false;
            continue;
        }
        std::uint64_t count = field.size;
        if (count == 0) {
            std::uint32_t n = 0;
            if (!at.read(&n))
                return false;
            if (field.bound > 0 && n > field.bound)
                return at.fail(QStringLiteral("'%1' has %2 elements, more than its bound %3")
                                   .arg(field.name)
                                   .arg(n)
                                   .arg(field.bound));
            count = n;
        }
        const std::uint64_t each = field.primitive == Primitive::Complex
                                       ? std::uint64_t(m_minSize[size_t(field.type)])
                                       : sizeOf(field.primitive);
        if (each == 0 ? count > MaxEmptyElements : count > (at.size - at.pos) / each)
            return at.fail(QStringLiteral("'%1' claims %2 elements, more than the message holds")
                               .arg(field.name)
                               .arg(count));
        bool anyTake = false;
        if (takes) {
            for (const Take &t : *takes)
                anyTake = anyTake || t.field == f;
        }
        if (!anyTake && MsgSchema::isNumber(field.primitive)) {
            // Numbers no path wants: one alignment, then past them all.
            if (count > 0 && (!at.align(each) || !at.need(count * each)))
                return false;
            at.pos += std::size_t(count * each);
            continue;
        }
        for (std::uint64_t e = 0; e < count; ++e) {
            if (!value(at, field, anyTake ? takeOf(f, int(e)) : nullptr))
                return false;
        }
    }
    return true;
}

bool CdrDecoder::value(Cursor &at, const MsgSchema::Field &field, const Take *take)
{
    switch (field.primitive) {
    case Primitive::String:
    case Primitive::WString: {
        std::uint32_t length = 0;
        if (!at.read(&length))
            return false;
        const std::uint64_t bytes =
            std::uint64_t(length) * (field.primitive == Primitive::WString ? 4 : 1);
        if (!at.need(bytes))
            return false;
        at.pos += std::size_t(bytes);
        return true;
    }
    case Primitive::Complex:
        return walk(at, field.type, take ? take->node : -1);
    default: {
        double v = 0.0;
        if (!at.number(field.primitive, &v))
            return false;
        if (take && take->slot >= 0)
            m_leaves[size_t(take->slot)] = v;
        return true;
    }
    }
}

} // namespace semhap
