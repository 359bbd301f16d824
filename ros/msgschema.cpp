// SPDX-License-Identifier: MIT
#include "msgschema.h"

#include <QHash>
#include <QRegularExpression>
#include <QSet>

#include <functional>

namespace semhap {

namespace {

struct Builtin
{
    const char *name;
    MsgSchema::Primitive primitive;
};

const Builtin Builtins[] = {
    {"bool", MsgSchema::Primitive::Bool},       {"byte", MsgSchema::Primitive::Byte},
    {"char", MsgSchema::Primitive::Char},       {"int8", MsgSchema::Primitive::Int8},
    {"uint8", MsgSchema::Primitive::UInt8},     {"int16", MsgSchema::Primitive::Int16},
    {"uint16", MsgSchema::Primitive::UInt16},   {"int32", MsgSchema::Primitive::Int32},
    {"uint32", MsgSchema::Primitive::UInt32},   {"int64", MsgSchema::Primitive::Int64},
    {"uint64", MsgSchema::Primitive::UInt64},   {"float32", MsgSchema::Primitive::Float32},
    {"float64", MsgSchema::Primitive::Float64}, {"string", MsgSchema::Primitive::String},
    {"wstring", MsgSchema::Primitive::WString},
};

/** package/msg/Type and package/Type name one type. */
QString canonical(const QString &name)
{
    QString out = name;
    out.replace(QLatin1String("/msg/"), QLatin1String("/"));
    return out;
}

QString package(const QString &type)
{
    const qsizetype slash = type.indexOf(QLatin1Char('/'));
    return slash < 0 ? QString() : type.left(slash);
}

/** A field whose type is another message, by name until every type is known. */
struct Pending
{
    size_t type;
    size_t field;
    QString name;
    int line;
    int column;
};

} // namespace

bool MsgSchema::parse(const QString &name, const QByteArray &text, MsgSchema *schema,
                      QString *error)
{
    static const QRegularExpression rule(QStringLiteral("^=+$"));
    static const QRegularExpression fieldName(QStringLiteral("^[A-Za-z][A-Za-z0-9_]*$"));
    static const QRegularExpression typeToken(
        QStringLiteral("^([A-Za-z][A-Za-z0-9_/]*)(?:<=([0-9]+))?(?:\\[(?:(<=)?([0-9]+))?\\])?$"));

    MsgSchema s;
    std::vector<Pending> pending;
    const auto fail = [&](int line, int column, const QString &reason) {
        *error = QStringLiteral("%1:%2: %3").arg(line).arg(column).arg(reason);
        return false;
    };
    s.m_types.push_back({canonical(name), {}});
    // Lookups by hash, so that a schema of many types or fields costs linear time.
    QHash<QString, int> index{{s.m_types.front().name, 0}};
    QSet<QString> names; // the fields of the type being read
    const QStringList lines = QString::fromUtf8(text).split(QLatin1Char('\n'));
    bool expectHeader = false;
    for (int i = 0; i < lines.size(); ++i) {
        const int lineNo = i + 1;
        QString line = lines[i];
        const qsizetype hash = line.indexOf(QLatin1Char('#'));
        if (hash >= 0)
            line.truncate(hash);
        const QString trimmed = line.trimmed();
        if (trimmed.isEmpty())
            continue;
        const int indent = int(line.indexOf(trimmed.front())) + 1;
        if (rule.match(trimmed).hasMatch()) {
            expectHeader = true;
            continue;
        }
        if (expectHeader) {
            if (!trimmed.startsWith(QLatin1String("MSG:")))
                return fail(lineNo, indent,
                            QStringLiteral("expected 'MSG: package/Type' after "
                                           "a line of '='"));
            const QString type = canonical(trimmed.mid(4).trimmed());
            if (package(type).isEmpty())
                return fail(lineNo, indent,
                            QStringLiteral("expected 'MSG: package/Type', got "
                                           "'%1'")
                                .arg(trimmed));
            if (index.contains(type))
                return fail(lineNo, indent, QStringLiteral("type %1 is defined twice").arg(type));
            index.insert(type, int(s.m_types.size()));
            s.m_types.push_back({type, {}});
            names.clear();
            expectHeader = false;
            continue;
        }
        // TYPE NAME [DEFAULT] or TYPE NAME=CONSTANT
        const QStringList tokens = trimmed.split(QRegularExpression(QStringLiteral("\\s+")));
        if (tokens.size() < 2)
            return fail(lineNo, indent,
                        QStringLiteral("expected 'TYPE NAME', got '%1'").arg(trimmed));
        const qsizetype nameColumn = line.indexOf(tokens[1], indent - 1 + tokens[0].size()) + 1;
        if (tokens[1].contains(QLatin1Char('=')) ||
            (tokens.size() > 2 && tokens[2].startsWith(QLatin1Char('='))))
            continue; // a constant: not in the message's bytes
        if (!fieldName.match(tokens[1]).hasMatch())
            return fail(lineNo, int(nameColumn),
                        QStringLiteral("'%1' is not a field name").arg(tokens[1]));
        const QRegularExpressionMatch match = typeToken.match(tokens[0]);
        if (!match.hasMatch())
            return fail(lineNo, indent, QStringLiteral("'%1' is not a type").arg(tokens[0]));
        Field field;
        field.name = tokens[1];
        const QString base = match.captured(1);
        const bool hasArray = tokens[0].endsWith(QLatin1Char(']'));
        field.array = hasArray;
        bool ok = true;
        if (!match.captured(4).isEmpty()) {
            const std::uint32_t n = match.captured(4).toUInt(&ok);
            if (!ok)
                return fail(lineNo, indent,
                            QStringLiteral("'%1': array size out of range").arg(tokens[0]));
            if (match.captured(3).isEmpty()) {
                if (n == 0)
                    return fail(lineNo, indent,
                                QStringLiteral("'%1': an array of no elements").arg(tokens[0]));
                field.size = n;
            } else {
                field.bound = n;
            }
        }
        field.primitive = Primitive::Complex;
        for (const Builtin &b : Builtins) {
            if (base == QLatin1String(b.name))
                field.primitive = b.primitive;
        }
        if (!match.captured(2).isEmpty() && field.primitive != Primitive::String &&
            field.primitive != Primitive::WString)
            return fail(lineNo, indent,
                        QStringLiteral("'%1': only strings take a bound '<='").arg(tokens[0]));
        Type &owner = s.m_types.back();
        if (names.contains(field.name))
            return fail(lineNo, int(nameColumn),
                        QStringLiteral("field '%1' is defined twice").arg(field.name));
        names.insert(field.name);
        if (field.primitive == Primitive::Complex) {
            QString type = canonical(base);
            if (!type.contains(QLatin1Char('/')))
                type = type == QLatin1String("Header") &&
                               package(owner.name) != QLatin1String("std_msgs")
                           ? QStringLiteral("std_msgs/Header")
                           : package(owner.name) + QLatin1Char('/') + type;
            pending.push_back({s.m_types.size() - 1, owner.fields.size(), type, lineNo, indent});
        }
        owner.fields.push_back(field);
    }
    if (expectHeader)
        return fail(int(lines.size()), 1,
                    QStringLiteral("expected 'MSG: package/Type' after a "
                                   "line of '='"));

    for (const Pending &p : pending) {
        const int type = index.value(p.name, -1);
        if (type < 0) {
            QStringList defined;
            for (const Type &t : s.m_types) {
                if (defined.size() == 10) {
                    defined << QStringLiteral("…");
                    break;
                }
                defined << t.name;
            }
            return fail(p.line, p.column,
                        QStringLiteral("type %1 is not defined here (the "
                                       "schema defines %2)")
                            .arg(p.name, defined.join(QStringLiteral(", "))));
        }
        s.m_types[p.type].fields[p.field].type = type;
    }

    // A type may not hold itself, and nesting is bounded: each type's depth once.
    const int tooDeep = MaxDepth + 1;
    std::vector<int> height(s.m_types.size(), -1);
    std::vector<bool> visiting(s.m_types.size(), false);
    std::function<int(int, int)> depth = [&](int type, int level) -> int {
        if (level > MaxDepth || visiting[size_t(type)])
            return tooDeep;
        if (height[size_t(type)] >= 0)
            return height[size_t(type)];
        visiting[size_t(type)] = true;
        int deepest = 0;
        for (const Field &f : s.m_types[size_t(type)].fields) {
            if (f.primitive == Primitive::Complex)
                deepest = std::min(tooDeep, std::max(deepest, 1 + depth(f.type, level + 1)));
        }
        visiting[size_t(type)] = false;
        height[size_t(type)] = deepest;
        return deepest;
    };
    for (size_t t = 0; t < s.m_types.size(); ++t) {
        if (depth(int(t), 0) >= tooDeep)
            return fail(1, 1,
                        QStringLiteral("%1 nests types more than %2 deep, or holds itself")
                            .arg(s.m_types[t].name)
                            .arg(MaxDepth));
    }
    *schema = std::move(s);
    return true;
}

const MsgSchema::Field *MsgSchema::field(const Type &type, const QString &name)
{
    for (const Field &f : type.fields) {
        if (f.name == name)
            return &f;
    }
    return nullptr;
}

bool MsgSchema::isBuiltin(const QString &name)
{
    for (const Builtin &b : Builtins) {
        if (name == QLatin1String(b.name))
            return true;
    }
    return false;
}

bool MsgSchema::isNumber(Primitive primitive)
{
    return primitive != Primitive::String && primitive != Primitive::WString &&
           primitive != Primitive::Complex;
}

QString MsgSchema::typeName(const Field &field) const
{
    QString base;
    for (const Builtin &b : Builtins) {
        if (b.primitive == field.primitive)
            base = QLatin1String(b.name);
    }
    if (field.primitive == Primitive::Complex)
        base = m_types[size_t(field.type)].name;
    if (!field.array)
        return base;
    if (field.size > 0)
        return base + QStringLiteral("[%1]").arg(field.size);
    return base +
           (field.bound > 0 ? QStringLiteral("[<=%1]").arg(field.bound) : QStringLiteral("[]"));
}

} // namespace semhap
