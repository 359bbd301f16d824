// SPDX-License-Identifier: MIT
#include "largeinputs.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QString>

#include <algorithm>

namespace semhap {

QByteArray largeAhap(int events)
{
    QJsonArray pattern;
    for (int i = 0; i < events; ++i) {
        const double t = 0.02 * i;
        const double intensity = 0.3 + 0.6 * ((i * 37) % 100) / 100.0;
        const bool transient = i % 2 == 0;
        QJsonObject event{
            {"Time", t},
            {"EventType", transient ? "HapticTransient" : "HapticContinuous"},
            {"EventParameters",
             QJsonArray{
                 QJsonObject{{"ParameterID", "HapticIntensity"}, {"ParameterValue", intensity}},
                 QJsonObject{{"ParameterID", "HapticSharpness"}, {"ParameterValue", 0.5}}}}};
        if (!transient)
            event.insert("EventDuration", 0.015);
        pattern.append(QJsonObject{{"Event", event}});
        if (i % 100 == 50) {
            pattern.append(QJsonObject{
                {"ParameterCurve",
                 QJsonObject{{"ParameterID", "HapticIntensityControl"},
                             {"Time", t},
                             {"ParameterCurveControlPoints",
                              QJsonArray{QJsonObject{{"Time", 0.0}, {"ParameterValue", 1.0}},
                                         QJsonObject{{"Time", 0.5}, {"ParameterValue", 0.6}},
                                         QJsonObject{{"Time", 1.0}, {"ParameterValue", 1.0}}}}}}});
        }
    }
    return QJsonDocument(QJsonObject{{"Version", 1.0}, {"Pattern", pattern}})
        .toJson(QJsonDocument::Compact);
}

QByteArray largeHaptic(int points)
{
    QJsonArray amplitude;
    for (int i = 0; i < points; ++i) {
        QJsonObject point{{"time", 0.01 * i}, {"amplitude", 0.2 + 0.7 * ((i * 13) % 50) / 50.0}};
        if (i % 10 == 5)
            point.insert("emphasis", QJsonObject{{"amplitude", 1.0}, {"frequency", 0.5}});
        amplitude.append(point);
    }
    return QJsonDocument(
               QJsonObject{{"version", QJsonObject{{"major", 1}, {"minor", 0}, {"patch", 0}}},
                           {"signals",
                            QJsonObject{{"continuous",
                                         QJsonObject{{"envelopes",
                                                      QJsonObject{{"amplitude", amplitude}}}}}}}})
        .toJson(QJsonDocument::Compact);
}

QJsonObject largeRouter(int nodes)
{
    QJsonArray list;
    QJsonArray links;
    for (int d = 0; d < 8; ++d)
        list.append(QJsonObject{{"id", QString("band%1").arg(d)},
                                {"type", "device"},
                                {"params", QJsonObject{{"model", "lra4"}}}});
    const int chains = std::max(1, (nodes - 8) / 10);
    for (int c = 0; c < chains; ++c) {
        const QString id = QString("c%1").arg(c);
        list.append(
            QJsonObject{{"id", QString(id + ".force")},
                        {"type", "force"},
                        {"params", QJsonObject{{"gripper", QString(c % 2 ? "left" : "right")},
                                               {"grasp", 20}}}});
        QString previous = id + ".force";
        for (int f = 0; f < 8; ++f) {
            const QString filter = QString("%1.f%2").arg(id).arg(f);
            list.append(QJsonObject{{"id", filter},
                                    {"type", "filter"},
                                    {"params", QJsonObject{{"category", "confirmation"}}}});
            links.append(QJsonObject{{"from", previous}, {"to", filter}});
            previous = filter;
        }
        list.append(QJsonObject{{"id", QString(id + ".pattern")},
                                {"type", "pattern"},
                                {"params", QJsonObject{{"pattern", "vib.geiger"}}}});
        links.append(QJsonObject{{"from", previous}, {"to", QString(id + ".pattern")}});
        links.append(
            QJsonObject{{"from", QString(id + ".pattern")}, {"to", QString("band%1").arg(c % 8)}});
    }
    return QJsonObject{{"format", "semhap.router/1"}, {"nodes", list}, {"links", links}};
}

} // namespace semhap
