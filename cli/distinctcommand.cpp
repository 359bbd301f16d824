// SPDX-License-Identifier: MIT
#include "distinctcommand.h"

#include "distinctiveness.h"
#include "router.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace semhap {

namespace {

/** A distance as written: to 0.01 JND. */
double rounded(double jnd)
{
    return std::round(jnd * 100.0) / 100.0;
}

/** The matrix as text: a header of names, a row per name, distances to 0.01 JND. */
QByteArray matrixText(const QStringList &names, const std::vector<std::vector<double>> &distance)
{
    int width = 6;
    for (const QString &name : names)
        width = std::max(width, int(name.size()));
    QByteArray text = QByteArray(width, ' ');
    for (const QString &name : names)
        text += "  " + name.rightJustified(width).toUtf8();
    text += '\n';
    for (size_t i = 0; i < size_t(names.size()); ++i) {
        text += names[int(i)].leftJustified(width).toUtf8();
        for (double d : distance[i])
            text += "  " + QByteArray::number(rounded(d), 'f', 2).rightJustified(width);
        text += '\n';
    }
    return text;
}

QJsonArray matrixJson(const std::vector<std::vector<double>> &distance)
{
    QJsonArray rows;
    for (const std::vector<double> &row : distance) {
        QJsonArray values;
        for (double d : row)
            values.append(rounded(d));
        rows.append(values);
    }
    return rows;
}

} // namespace

QString DistinctCommand::summary() const
{
    return tr("Says how far apart patterns feel, in just-noticeable differences, as their bands "
              "render them; pairs under 1 JND are confusable.");
}

void DistinctCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("router"),
                                 tr("A router preset or file: the matrix of its messages on "
                                    "each band."),
                                 tr("[ROUTER]"));
    parser.addOption({QStringLiteral("patterns"),
                      tr("Compare these patterns (library names or files), comma-separated."),
                      tr("A,B,…")});
    parser.addOption({QStringLiteral("intensity"),
                      tr("The intensity each pattern plays at (default 0.5)."), tr("X")});
    parser.addOption({QStringLiteral("json"), tr("Write JSON instead of a table.")});
}

int DistinctCommand::execute(const QCommandLineParser &parser)
{
    double intensity = 0.5;
    if (!numberOption(parser, QStringLiteral("intensity"), &intensity))
        return ExitUsage;
    if (!(intensity >= 0.0 && intensity <= 1.0))
        return usageError(tr("--intensity must be between 0 and 1"));
    const QStringList positional = parser.positionalArguments();
    const bool patterns = parser.isSet(QStringLiteral("patterns"));
    if (positional.size() > 1 || (patterns && !positional.isEmpty()))
        return usageError(tr("unexpected argument '%1'").arg(positional.last()));
    if (!patterns && positional.isEmpty())
        return usageError(tr("a ROUTER or --patterns is required"));
    const bool json = parser.isSet(QStringLiteral("json"));
    return patterns ? comparePatterns(parser.value(QStringLiteral("patterns")), intensity, json)
                    : compareRouter(positional.first(), intensity, json);
}

int DistinctCommand::comparePatterns(const QString &list, double intensity, bool json)
{
    QStringList names = list.split(QLatin1Char(','));
    for (QString &name : names)
        name = name.trimmed();
    if (names.contains(QString()))
        return usageError(tr("--patterns has an empty name"));
    const Distinctiveness model;
    std::vector<Percept> percepts;
    for (const QString &name : names) {
        PatternPtr pattern;
        DeviceModelPtr device;
        if (!loadNamedPattern(name, &pattern, &device))
            return ExitInvalidInput;
        keepFromOutputs(name, Kept::Input);
        Percept percept;
        QString reason;
        if (!model.perceive(pattern, *device, intensity, &percept, &reason))
            return inputError(name + QStringLiteral(": ") + reason);
        percepts.push_back(percept);
    }
    std::vector<std::vector<double>> distance(percepts.size(),
                                              std::vector<double>(percepts.size(), 0.0));
    for (size_t i = 0; i < percepts.size(); ++i) {
        for (size_t j = 0; j < percepts.size(); ++j)
            distance[i][j] = model.distance(percepts[i], percepts[j]).total;
    }

    if (json) {
        const QJsonObject out{{QStringLiteral("patterns"), QJsonArray::fromStringList(names)},
                              {QStringLiteral("intensity"), intensity},
                              {QStringLiteral("distance"), matrixJson(distance)}};
        m_out << QJsonDocument(out).toJson(QJsonDocument::Compact) << '\n';
        return ExitOk;
    }
    m_out << tr("Distance in JND at intensity %1:").arg(intensity) << '\n'
          << matrixText(names, distance);
    return ExitOk;
}

int DistinctCommand::compareRouter(const QString &name, double intensity, bool json)
{
    LoadError error;
    std::unique_ptr<Router> router = loadRouter(name, {}, &error);
    if (!router)
        return inputError(error.toString());
    reportWarnings(router->graph());
    keepFromOutputs(name, Kept::Input);
    std::vector<BandDistinctiveness> bands;
    QString reason;
    if (!Distinctiveness().bands(*router, intensity, &bands, &reason))
        return inputError(name + QStringLiteral(": ") + reason);

    if (json) {
        QJsonArray list;
        for (const BandDistinctiveness &band : bands) {
            QJsonArray confusable;
            for (const BandDistinctiveness::Pair &pair : band.confusable)
                confusable.append(QJsonArray{band.messages[pair.a], band.messages[pair.b],
                                             rounded(pair.distance)});
            list.append(QJsonObject{{QStringLiteral("device"), band.device},
                                    {QStringLiteral("model"), band.model},
                                    {QStringLiteral("messages"),
                                     QJsonArray::fromStringList(band.messages)},
                                    {QStringLiteral("distance"), matrixJson(band.distance)},
                                    {QStringLiteral("confusable"), confusable}});
        }
        const QJsonObject out{{QStringLiteral("router"), router->graph().name},
                              {QStringLiteral("intensity"), intensity},
                              {QStringLiteral("bands"), list}};
        m_out << QJsonDocument(out).toJson(QJsonDocument::Compact) << '\n';
        return ExitOk;
    }
    for (const BandDistinctiveness &band : bands) {
        m_out << tr("%1 (%2), distance in JND at intensity %3:")
                     .arg(band.device, band.model)
                     .arg(intensity)
              << '\n'
              << matrixText(band.messages, band.distance);
        for (const BandDistinctiveness::Pair &pair : band.confusable)
            m_out << tr("confusable: %1 and %2, %3 JND apart")
                         .arg(band.messages[pair.a], band.messages[pair.b])
                         .arg(rounded(pair.distance), 0, 'f', 2)
                  << '\n';
        m_out << '\n';
    }
    return ExitOk;
}

} // namespace semhap
