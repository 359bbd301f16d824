// SPDX-License-Identifier: MIT
#include "semanticevent.h"

namespace semhap {

namespace {

// One table per enum, in enum order, so names and parsing cannot drift apart.
template<typename Enum, size_t Count>
bool fromName(const QLatin1String (&names)[Count], const QString &name, Enum *value)
{
    for (size_t i = 0; i < Count; ++i) {
        if (name == names[i]) {
            *value = Enum(i);
            return true;
        }
    }
    return false;
}

const QLatin1String categoryNames[] = {QLatin1String("confirmation"), QLatin1String("exception")};
const QLatin1String eventPhaseNames[] = {QLatin1String("begin"), QLatin1String("update"),
                                         QLatin1String("end")};

} // namespace

NameTable &messageNames()
{
    static NameTable table(
        {QStringLiteral("grasp"), QStringLiteral("break"), QStringLiteral("slip")});
    return table;
}

QString messageName(Message message)
{
    return messageNames().name(int(message));
}

QString categoryName(Category category)
{
    return categoryNames[size_t(category)];
}

QString eventPhaseName(EventPhase phase)
{
    return eventPhaseNames[size_t(phase)];
}

bool messageFromName(const QString &name, Message *message)
{
    if (!isPlainName(name))
        return false;
    const int id = messageNames().intern(name);
    if (id < 0)
        return false;
    *message = Message(id);
    return true;
}

bool isBuiltinMessage(Message message)
{
    return int(message) >= int(Message::Grasp) && int(message) <= int(Message::Slip);
}

bool categoryFromName(const QString &name, Category *category)
{
    return fromName(categoryNames, name, category);
}

bool eventPhaseFromName(const QString &name, EventPhase *phase)
{
    return fromName(eventPhaseNames, name, phase);
}

Category categoryOf(Message message)
{
    return message == Message::Grasp ? Category::Confirmation : Category::Exception;
}

} // namespace semhap
