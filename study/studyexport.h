// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

#include <vector>

namespace semhap {

class StudyDatabase;
struct StudyAnalysis;

/**
 * The files a study's results are handed over in (docs/studies.md, "Export"), as names and
 * bytes, so `semhap study` and the studio write the same ones, each the safe way of its own.
 */
class StudyExport
{
public:
    /** One file: its name in the folder, its contents. */
    struct File
    {
        QString name;
        QByteArray bytes;
    };

    /**
     * `measures.csv` (the tidy table), `trials.csv` (every practice round and trial with
     * its status) and `answers.csv` (every current answer, notes as text). Empty, with
     * `error`, when the study read short (readError()).
     */
    static std::vector<File> results(const StudyDatabase &study, QString *error);
    /**
     * `measures.csv` and `analysis.R`, which computes `study analyze`'s tests from it in R
     * (StudyRScript). Empty, with `error`, when the study read short.
     */
    static std::vector<File> rAnalysis(const StudyDatabase &study, QString *error);
    /** `report.md` and a box plot per measure. */
    static std::vector<File> report(const StudyAnalysis &analysis);
    /** The folder a report goes in beside the results (the studio's export). */
    static constexpr const char *ReportFolder = "report";
};

} // namespace semhap
