// SPDX-License-Identifier: MIT
#include "exportcommand.h"

#include "csvrow.h"
#include "jsonlineswriter.h"
#include "mcapexport.h"
#include "nametable.h"
#include "sessionreader.h"
#include "xdfexport.h"

#include <QDir>
#include <QJsonDocument>

#include <cmath>
#include <map>

namespace semhap {

namespace {

using CsvRow::appendNumber;
using CsvRow::appendText;

void appendFingertip(QByteArray &row, const Fingertip &tip, const ActorTable &actors)
{
    appendNumber(row, tip.f);
    row += ',';
    row += QByteArray::number(tip.n);
    row += ',';
    appendText(row, actors.name(tip.actor));
    for (double component : tip.fxyz) {
        row += ',';
        if (tip.hasFxyz)
            appendNumber(row, component);
    }
    row += ',';
    if (tip.mu > 0.0)
        appendNumber(row, tip.mu);
}

} // namespace

QString ExportCommand::summary() const
{
    return tr("Exports a session to CSV (one file per stream, for pandas or PlotJuggler), to "
              "JSON Lines in the spec's stream formats, to MCAP or to XDF.");
}

void ExportCommand::configure(QCommandLineParser &parser)
{
    parser.addPositionalArgument(QStringLiteral("session"), tr("The session database."),
                                 tr("SESSION"));
    parser.addOption({QStringLiteral("csv"),
                      tr("Write contact_frames.csv, signals.csv, events.csv, device_frames.csv, "
                         "operator_input.csv and metadata.json into DIR."),
                      tr("DIR")});
    parser.addOption({QStringLiteral("jsonl"),
                      tr("Write frames.jsonl, events.jsonl and device_frames.jsonl into DIR."),
                      tr("DIR")});
    parser.addOption({QStringLiteral("mcap"),
                      tr("Write FILE.mcap, which Foxglove, PlotJuggler, Rerun and ros2 bag open: "
                         "every frame as ROS 2 messages (docs/ros.md)."),
                      tr("FILE.mcap")});
    parser.addOption({QStringLiteral("xdf"),
                      tr("Write FILE.xdf, the Lab Streaming Layer's format: the fingertip "
                         "forces, the events as markers, the devices' output and the operator's "
                         "input as streams (docs/science.md)."),
                      tr("FILE.xdf")});
    parser.addOption({QStringLiteral("time"),
                      tr("With --xdf, the clock of the time stamps: session (its seconds, with "
                         "clock offsets onto LSL's clock) or lsl (LSL's clock itself)."),
                      tr("CLOCK"), QStringLiteral("session")});
}

int ExportCommand::execute(const QCommandLineParser &parser)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.isEmpty())
        return usageError(tr("a session file is required"));
    if (positional.size() > 1)
        return usageError(tr("unexpected argument '%1'").arg(positional.at(1)));
    if (!parser.isSet(QStringLiteral("csv")) && !parser.isSet(QStringLiteral("jsonl")) &&
        !parser.isSet(QStringLiteral("mcap")) && !parser.isSet(QStringLiteral("xdf")))
        return usageError(tr("--csv DIR, --jsonl DIR, --mcap FILE or --xdf FILE is required"));
    const QString clock = parser.value(QStringLiteral("time"));
    if (clock != QLatin1String("session") && clock != QLatin1String("lsl"))
        return usageError(tr("--time: '%1' is not a clock (session or lsl)").arg(clock));
    if (parser.isSet(QStringLiteral("time")) && !parser.isSet(QStringLiteral("xdf")))
        return usageError(tr("--time goes with --xdf"));
    QString error;
    std::unique_ptr<SessionReader> session = SessionReader::open(positional.first(), &error);
    if (!session)
        return inputError(error);
    session->setRowErrorHandler([this](const QString &line) { report(line); });
    keepFromOutputs(session->path(), Kept::Input);
    if (parser.isSet(QStringLiteral("csv")) &&
        !exportCsv(*session, parser.value(QStringLiteral("csv"))))
        return ExitInvalidInput;
    if (parser.isSet(QStringLiteral("jsonl")) &&
        !exportJsonLines(*session, parser.value(QStringLiteral("jsonl"))))
        return ExitInvalidInput;
    if (parser.isSet(QStringLiteral("mcap"))) {
        QIODevice *out = openOutput(parser.value(QStringLiteral("mcap")));
        if (!out)
            return ExitInvalidInput;
        if (!McapExport::write(*session, out, &error)) {
            const OutputFile *failed = failedOutput();
            return inputError(failed ? failed->writeError().toString() : error);
        }
    }
    if (parser.isSet(QStringLiteral("xdf"))) {
        QIODevice *out = openOutput(parser.value(QStringLiteral("xdf")));
        if (!out)
            return ExitInvalidInput;
        QStringList notes;
        const bool written =
            XdfExport::write(*session, out,
                             clock == QLatin1String("lsl") ? XdfExport::TimeBase::Lsl
                                                           : XdfExport::TimeBase::Session,
                             &notes, &error);
        for (const QString &note : std::as_const(notes))
            report(note);
        if (!written) {
            const OutputFile *failed = failedOutput();
            return inputError(failed ? failed->writeError().toString() : error);
        }
    }
    reportSkippedRows(*session);
    return ExitOk;
}

bool ExportCommand::exportCsv(SessionReader &session, const QString &dir)
{
    QString error;
    QByteArray row;
    const auto fail = [this, &error] {
        // A callback that stops on a failed write leaves the reader's error empty.
        const OutputFile *failed = failedOutput();
        inputError(failed ? failed->writeError().toString() : error);
        return false;
    };

    QIODevice *frames = openOutputIn(dir, QStringLiteral("contact_frames.csv"));
    if (!frames)
        return false;
    QByteArray header = "t,gripper";
    for (const char *tip : {"left", "right"}) {
        for (const char *column : {"f", "n", "actor", "fx", "fy", "fz", "mu"})
            header += QByteArray(",") + tip + '_' + column;
    }
    frames->write(header + ",arrival\n");
    // The frames' named signals, tidy: one row per signal per frame.
    QIODevice *signalRows = openOutputIn(dir, QStringLiteral("signals.csv"));
    if (!signalRows)
        return false;
    signalRows->write("t,gripper,signal,value\n");
    const bool framesOk = session.readContactFrames(
        [&](const ContactFrame &frame, double arrival) {
            for (const SignalValue &signal : frame.signalValues) {
                row.clear();
                appendNumber(row, frame.t);
                row += ',' + gripperName(frame.gripper).toUtf8() + ',';
                row += signalNames().name(signal.id).toUtf8() + ',';
                appendNumber(row, signal.value);
                row += '\n';
                if (signalRows->write(row) != row.size())
                    return false;
            }
            row.clear();
            appendNumber(row, frame.t);
            row += ',' + gripperName(frame.gripper).toUtf8() + ',';
            appendFingertip(row, frame.left, session.actors());
            row += ',';
            appendFingertip(row, frame.right, session.actors());
            row += ',';
            appendNumber(row, arrival);
            row += '\n';
            return frames->write(row) == row.size();
        },
        &error);
    if (!framesOk)
        return fail();

    QIODevice *events = openOutputIn(dir, QStringLiteral("events.csv"));
    if (!events)
        return false;
    events->write("t,gripper,node,detector,message,category,phase,intensity\n");
    const bool eventsOk = session.readEvents(
        [&](const SemanticEvent &event) {
            row.clear();
            appendNumber(row, event.t);
            row += ',' + gripperName(event.gripper).toUtf8() + ',';
            appendText(row, session.nodeNames().value(event.node));
            for (const QString &name :
                 {detectorKindName(event.detector), messageName(event.message),
                  categoryName(event.category), eventPhaseName(event.phase)})
                row += ',' + name.toUtf8();
            row += ',';
            appendNumber(row, event.intensity);
            row += '\n';
            return events->write(row) == row.size();
        },
        &error);
    if (!eventsOk)
        return fail();

    // One row per instant, one column per device channel: devices at other rates leave
    // their columns empty, which pandas and PlotJuggler read as missing.
    QIODevice *devices = openOutputIn(dir, QStringLiteral("device_frames.csv"));
    if (!devices)
        return false;
    std::vector<int> firstColumn;
    int columns = 0;
    header = "t";
    for (int d = 0; d < session.deviceNames().size(); ++d) {
        firstColumn.push_back(columns);
        for (const QString &channel : session.channelNames(d)) {
            header += ',';
            appendText(header, session.deviceNames().at(d) + QLatin1Char('.') + channel);
            ++columns;
        }
    }
    devices->write(header + '\n');
    std::vector<double> values(size_t(columns), qQNaN());
    double instant = qQNaN();
    const auto writeInstant = [&] {
        if (std::isnan(instant))
            return true;
        row.clear();
        appendNumber(row, instant);
        for (double value : values) {
            row += ',';
            appendNumber(row, value);
        }
        row += '\n';
        std::fill(values.begin(), values.end(), qQNaN());
        return devices->write(row) == row.size();
    };
    const bool devicesOk = session.readDeviceFrames(
        [&](const DeviceFrame &frame) {
            if (frame.t != instant && !writeInstant())
                return false;
            instant = frame.t;
            if (size_t(frame.device) >= firstColumn.size())
                return true; // a device the devices table does not list: no column for it
            const int count =
                std::min(frame.channelCount, int(session.channelNames(frame.device).size()));
            for (int c = 0; c < count; ++c)
                values[size_t(firstColumn[size_t(frame.device)] + c)] = frame.values[size_t(c)];
            return true;
        },
        &error);
    if (!devicesOk || !writeInstant())
        return fail();

    QIODevice *inputs = openOutputIn(dir, QStringLiteral("operator_input.csv"));
    if (!inputs)
        return false;
    inputs->write("t,hand,x,y,z,qw,qx,qy,qz,grip\n");
    const bool inputsOk = session.readHandCommands(
        [&](const HandCommand &input) {
            row.clear();
            appendNumber(row, input.t);
            row += ',' + gripperName(input.hand).toUtf8();
            for (double v : input.target.pos) {
                row += ',';
                appendNumber(row, v);
            }
            for (double v : input.target.quat) {
                row += ',';
                appendNumber(row, v);
            }
            row += ',';
            appendNumber(row, input.grip);
            row += '\n';
            return inputs->write(row) == row.size();
        },
        &error);
    if (!inputsOk)
        return fail();

    QIODevice *metadata = openOutputIn(dir, QStringLiteral("metadata.json"));
    if (!metadata)
        return false;
    metadata->write(QJsonDocument(session.info().toJson()).toJson(QJsonDocument::Indented));
    return true;
}

bool ExportCommand::exportJsonLines(SessionReader &session, const QString &dir)
{
    QIODevice *framesOut = openOutputIn(dir, QStringLiteral("frames.jsonl"));
    QIODevice *eventsOut = framesOut ? openOutputIn(dir, QStringLiteral("events.jsonl")) : nullptr;
    QIODevice *devicesOut =
        eventsOut ? openOutputIn(dir, QStringLiteral("device_frames.jsonl")) : nullptr;
    if (!devicesOut)
        return false;
    JsonLinesWriter frames(framesOut);
    frames.setActorTable(&session.actors());
    QString error;
    bool ok = session.readContactFrames(
        [&frames](const ContactFrame &frame, double) { return frames.write(frame); }, &error);
    // Events and device frames name nodes and devices as read, so read them first.
    std::vector<SemanticEvent> events;
    ok = ok && session.readEvents(
                   [&events](const SemanticEvent &event) {
                       events.push_back(event);
                       return true;
                   },
                   &error);
    JsonLinesWriter eventWriter(eventsOut);
    eventWriter.setNodeNames(session.nodeNames());
    for (const SemanticEvent &event : events)
        ok = ok && eventWriter.write(event);
    JsonLinesWriter deviceWriter(devicesOut);
    deviceWriter.setDeviceNames(session.deviceNames());
    ok = ok && session.readDeviceFrames(
                   [&deviceWriter](const DeviceFrame &frame) { return deviceWriter.write(frame); },
                   &error);
    if (!ok) {
        const OutputFile *failed = failedOutput();
        inputError(failed ? failed->writeError().toString() : error);
    }
    return ok;
}

} // namespace semhap
