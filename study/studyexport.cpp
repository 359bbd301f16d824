// SPDX-License-Identifier: MIT
#include "studyexport.h"

#include "csvrow.h"
#include "studyanalysis.h"
#include "studydatabase.h"
#include "studyrscript.h"
#include "studytable.h"

#include <cmath>

namespace semhap {

std::vector<StudyExport::File> StudyExport::rAnalysis(const StudyDatabase &study, QString *error)
{
    const StudyTable table = StudyTable::fromStudy(study);
    if (!study.readError().isEmpty()) {
        *error = study.readError();
        return {};
    }
    StudyAnalysis analysis = StudyAnalysis::run(table);
    analysis.name = study.protocol().name;
    return {{QStringLiteral("measures.csv"), table.toCsv()},
            {QStringLiteral("analysis.R"), StudyRScript::script(analysis, table)}};
}

std::vector<StudyExport::File> StudyExport::results(const StudyDatabase &study, QString *error)
{
    const StudyProtocol &protocol = study.protocol();
    const auto conditionId = [&](int condition) {
        return condition >= 0 ? protocol.conditions[size_t(condition)].id : QString();
    };
    std::vector<File> files;
    files.push_back({QStringLiteral("measures.csv"), StudyTable::fromStudy(study).toCsv()});

    QByteArray csv = "participant,condition,phase,trial,status,reason,seconds,started,ended,"
                     "session\n";
    for (const StudyDatabase::Trial &t : study.trials()) {
        for (const QString &field :
             {t.participant, conditionId(t.condition),
              t.practice ? QStringLiteral("practice") : QStringLiteral("trial")}) {
            CsvRow::appendText(csv, field);
            csv += ',';
        }
        if (!t.practice)
            csv += QByteArray::number(t.number);
        csv += ',';
        CsvRow::appendText(csv, statusName(t.status));
        csv += ',';
        CsvRow::appendText(csv, t.reason);
        csv += ',';
        CsvRow::appendNumber(csv, std::round(t.seconds * 1000.0) / 1000.0); // to the ms
        for (const QString &field : {t.started.toString(Qt::ISODateWithMs),
                                     t.ended.toString(Qt::ISODateWithMs), t.session}) {
            csv += ',';
            CsvRow::appendText(csv, field);
        }
        csv += '\n';
    }
    files.push_back({QStringLiteral("trials.csv"), csv});

    csv = "participant,condition,measure,value,text,answered\n";
    for (const StudyDatabase::Answer &a : study.answers()) {
        for (const QString &field : {a.participant, conditionId(a.condition), a.measure}) {
            CsvRow::appendText(csv, field);
            csv += ',';
        }
        CsvRow::appendNumber(csv, a.value);
        csv += ',';
        CsvRow::appendText(csv, a.text);
        csv += ',';
        CsvRow::appendText(csv, a.answered.toString(Qt::ISODateWithMs));
        csv += '\n';
    }
    files.push_back({QStringLiteral("answers.csv"), csv});
    // A damaged study reads short: nothing half is handed over.
    if (!study.readError().isEmpty()) {
        *error = study.readError();
        return {};
    }
    return files;
}

std::vector<StudyExport::File> StudyExport::report(const StudyAnalysis &analysis)
{
    std::vector<File> files{{QStringLiteral("report.md"), analysis.markdown()}};
    for (const StudyAnalysis::Measure &m : analysis.measures)
        files.push_back({StudyAnalysis::plotFile(m.name), analysis.boxPlotSvg(m)});
    return files;
}

} // namespace semhap
