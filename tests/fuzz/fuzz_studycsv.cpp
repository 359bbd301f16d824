// SPDX-License-Identifier: MIT
// A study's tidy CSV (`semhap study analyze DATA.csv`): parse, write back, read again the
// same, and analyse what was read.
#include "studyanalysis.h"
#include "studytable.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    semhap::StudyTable table;
    semhap::LoadError error;
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    if (!semhap::StudyTable::parseCsv(bytes, QStringLiteral("fuzz"), &table, &error)) {
        if (!error.isSet() || error.line < 1)
            std::abort(); // every refusal is located
        return 0;
    }
    semhap::StudyTable again;
    if (!semhap::StudyTable::parseCsv(table.toCsv(), QStringLiteral("again"), &again, &error) ||
        again.toCsv() != table.toCsv())
        std::abort();
    const semhap::StudyAnalysis analysis = semhap::StudyAnalysis::run(table);
    for (const semhap::StudyAnalysis::Measure &m : analysis.measures)
        analysis.boxPlotSvg(m);
    analysis.markdown();
    return 0;
}
