// SPDX-License-Identifier: MIT
#include "studytable.h"

#include "csvrow.h"
#include "inputfile.h"
#include "studydatabase.h"

#include <QJsonObject>
#include <QRegularExpression>

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <tuple>

namespace semhap {

namespace {

/** One CSV field and where it began. */
struct Field
{
    QString text;
    int column = 1;
};

/**
 * Splits `bytes` into records of fields (RFC 4180: quoted fields may hold commas, quotes
 * doubled, and line breaks); false with the place of an unterminated quote.
 */
bool splitCsv(const QByteArray &bytes, const QString &path,
              std::vector<std::vector<Field>> *records, std::vector<int> *lines, LoadError *error)
{
    std::vector<Field> record;
    QByteArray field;
    int line = 1, column = 1, fieldColumn = 1, recordLine = 1;
    bool quoted = false, wasQuoted = false;
    const auto endField = [&] {
        record.push_back({QString::fromUtf8(field), fieldColumn});
        field.clear();
        wasQuoted = false;
    };
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        const char c = bytes[i];
        if (quoted) {
            if (c == '"' && i + 1 < bytes.size() && bytes[i + 1] == '"') {
                field += '"';
                ++i;
                column += 2;
                continue;
            }
            if (c == '"')
                quoted = false;
            else
                field += c;
            if (c == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
            continue;
        }
        if (c == '"' && field.isEmpty() && !wasQuoted) {
            quoted = wasQuoted = true;
        } else if (c == ',') {
            endField();
            fieldColumn = column + 1;
        } else if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < bytes.size() && bytes[i + 1] == '\n')
                ++i;
            endField();
            records->push_back(record);
            lines->push_back(recordLine);
            record.clear();
            ++line;
            recordLine = line;
            column = 0;
            fieldColumn = 1;
        } else {
            field += c;
        }
        ++column;
    }
    if (quoted) {
        *error =
            LoadError::atLine(path, line, column, QStringLiteral("a quoted field never ends"));
        return false;
    }
    if (!field.isEmpty() || !record.empty()) {
        endField();
        records->push_back(record);
        lines->push_back(recordLine);
    }
    return true;
}

} // namespace

void StudyTable::add(const QString &participant, const QString &condition, int trial,
                     const QString &measure, double value)
{
    if (!m_conditionIndex.contains(condition)) {
        m_conditionIndex.insert(condition, int(m_conditions.size()));
        m_conditions.append(condition);
    }
    if (!m_participantIndex.contains(participant)) {
        m_participantIndex.insert(participant, int(m_participants.size()));
        m_participants.append(participant);
    }
    if (!m_rowsOfMeasure.contains(measure))
        m_measures.append(measure);
    m_rowsOfMeasure[measure].push_back(m_rows.size());
    m_rows.push_back({participant, condition, trial, measure, value});
}

StudyTable StudyTable::fromStudy(const StudyDatabase &study)
{
    StudyTable table;
    const StudyProtocol &protocol = study.protocol();
    for (const StudyProtocol::Condition &condition : protocol.conditions) {
        table.m_conditionIndex.insert(condition.id, int(table.m_conditions.size()));
        table.m_conditions.append(condition.id);
        table.m_levels.append(condition.levels);
    }
    table.m_factors = protocol.factors;
    for (const QString &participant : study.participants()) {
        table.m_participantIndex.insert(participant, int(table.m_participants.size()));
        table.m_participants.append(participant);
    }
    std::vector<Row> rows;
    for (const StudyDatabase::Trial &trial : study.trials()) {
        if (trial.practice || trial.status != StudyDatabase::Status::Done)
            continue;
        for (auto it = trial.metrics.begin(); it != trial.metrics.end(); ++it) {
            if (it.value().isDouble())
                rows.push_back({trial.participant, protocol.conditions[size_t(trial.condition)].id,
                                trial.number, it.key(), it.value().toDouble()});
        }
    }
    // The answers about a condition (a final item about none lives in answers.csv); a
    // complete NASA-TLX adds its raw score.
    std::map<std::pair<QString, int>, std::vector<double>> tlx;
    for (const StudyDatabase::Answer &answer : study.answers()) {
        if (std::isnan(answer.value) || answer.condition < 0)
            continue;
        rows.push_back({answer.participant, protocol.conditions[size_t(answer.condition)].id, 0,
                        answer.measure, answer.value});
        if (StudyProtocol::tlxSubscales().contains(answer.measure))
            tlx[{answer.participant, answer.condition}].push_back(answer.value);
    }
    for (const auto &[key, values] : tlx) {
        if (values.size() != size_t(StudyProtocol::tlxSubscales().size()))
            continue;
        double sum = 0;
        for (double v : values)
            sum += v;
        rows.push_back({key.first, protocol.conditions[size_t(key.second)].id, 0,
                        QLatin1String(RawTlx), sum / double(values.size())});
    }
    // Participant by participant in the order added, conditions in the protocol's order,
    // trials in theirs, a condition's answers after its trials: read back from the CSV, the
    // conditions come in the protocol's order again.
    const auto rank = [&](const Row &row) {
        return std::make_tuple(table.m_participantIndex.value(row.participant),
                               table.m_conditionIndex.value(row.condition),
                               row.trial == 0 ? INT_MAX : row.trial);
    };
    std::stable_sort(rows.begin(), rows.end(),
                     [&](const Row &a, const Row &b) { return rank(a) < rank(b); });
    for (const Row &row : rows)
        table.add(row.participant, row.condition, row.trial, row.measure, row.value);
    return table;
}

bool StudyTable::readCsv(const QString &path, StudyTable *out, LoadError *error)
{
    QByteArray bytes;
    QString reason;
    if (!InputFile::readDocument(path, &bytes, &reason)) {
        *error = LoadError::at(path, QString(), QStringLiteral("cannot read: ") + reason);
        return false;
    }
    return parseCsv(bytes, path, out, error);
}

bool StudyTable::parseCsv(QByteArray bytes, const QString &path, StudyTable *out, LoadError *error)
{
    if (bytes.startsWith("\xEF\xBB\xBF")) // a spreadsheet's byte-order mark
        bytes.remove(0, 3);
    std::vector<std::vector<Field>> records;
    std::vector<int> lines;
    if (!splitCsv(bytes, path, &records, &lines, error))
        return false;
    const QStringList header = QString::fromLatin1(Header).split(QLatin1Char(','));
    const auto fail = [&](size_t record, int column, const QString &why) {
        *error = LoadError::atLine(path, record < lines.size() ? lines[record] : 1, column, why);
        return false;
    };
    if (records.empty())
        return fail(0, 1,
                    QStringLiteral("empty; the first line must be %1").arg(QLatin1String(Header)));
    QStringList names;
    for (const Field &f : records[0])
        names.append(f.text.trimmed());
    if (names != header)
        return fail(0, 1,
                    QStringLiteral("the header must be exactly %1, got %2")
                        .arg(QLatin1String(Header), names.join(QLatin1Char(','))));
    StudyTable table;
    QHash<QString, int> lineOf; // each observation's line, to name a repeated one
    // Names from other tools may hold spaces ("No feedback"); not line breaks or controls.
    static const QRegularExpression namePattern(QStringLiteral("^[^\\x00-\\x1f\\x7f]{1,200}$"));
    for (size_t r = 1; r < records.size(); ++r) {
        const std::vector<Field> &f = records[r];
        if (f.size() == 1 && f[0].text.trimmed().isEmpty())
            continue; // a blank line
        if (f.size() != 5)
            return fail(r, 1, QStringLiteral("expected 5 fields, got %1").arg(f.size()));
        for (int i : {0, 1, 3}) {
            if (!namePattern.match(f[size_t(i)].text).hasMatch() ||
                f[size_t(i)].text.trimmed().isEmpty())
                return fail(r, f[size_t(i)].column,
                            QStringLiteral("%1 must be 1 to 200 characters, not blank and "
                                           "without line breaks or control characters")
                                .arg(header[i]));
        }
        int trial = 0;
        if (!f[2].text.isEmpty() && f[2].text != QLatin1String("NA")) {
            // pandas writes a column with empty cells as floats: 1.0
            bool ok = false;
            const double number = f[2].text.toDouble(&ok);
            ok = ok && number == std::floor(number) && number >= 1 && number <= 1000;
            trial = ok ? int(number) : 0;
            if (!ok)
                return fail(r, f[2].column,
                            QStringLiteral("trial must be a whole number from 1 to 1000 or "
                                           "empty, got '%1'")
                                .arg(f[2].text));
        }
        const QString text = f[4].text.trimmed();
        if (text.isEmpty() || text == QLatin1String("NA"))
            continue;
        bool ok = false;
        const double value = text.toDouble(&ok);
        if (!ok || !std::isfinite(value))
            return fail(r, f[4].column,
                        QStringLiteral("value must be a number, empty or NA, got '%1'").arg(text));
        const QString key =
            QStringList{f[0].text, f[1].text, QString::number(trial), f[3].text}.join(QChar(0));
        const auto seen = lineOf.constFind(key);
        if (seen != lineOf.cend())
            return fail(r, 1,
                        QStringLiteral("the same participant, condition, trial and "
                                       "measure as line %1")
                            .arg(seen.value()));
        lineOf.insert(key, lines[r]);
        const auto over = [&](const QHash<QString, int> &index, const QString &name, int limit) {
            return !index.contains(name) && index.size() >= limit;
        };
        if (over(table.m_conditionIndex, f[1].text, StudyProtocol::MaxConditions))
            return fail(
                r, f[1].column,
                QStringLiteral("more than %1 conditions").arg(StudyProtocol::MaxConditions));
        if (over(table.m_participantIndex, f[0].text, MaxParticipants))
            return fail(r, 1, QStringLiteral("more than %1 participants").arg(MaxParticipants));
        if (!table.m_rowsOfMeasure.contains(f[3].text) && table.m_measures.size() >= MaxMeasures)
            return fail(r, f[3].column, QStringLiteral("more than %1 measures").arg(MaxMeasures));
        table.add(f[0].text, f[1].text, trial, f[3].text, value);
    }
    *out = table;
    return true;
}

QByteArray StudyTable::toCsv() const
{
    QByteArray csv = QByteArray(Header) + '\n';
    for (const Row &row : m_rows) {
        CsvRow::appendText(csv, row.participant);
        csv += ',';
        CsvRow::appendText(csv, row.condition);
        csv += ',';
        if (row.trial > 0)
            csv += QByteArray::number(row.trial);
        csv += ',';
        CsvRow::appendText(csv, row.measure);
        csv += ',';
        CsvRow::appendNumber(csv, row.value);
        csv += '\n';
    }
    return csv;
}

StudyTable::Matrix StudyTable::matrix(const QString &measure) const
{
    // Sum and count per participant and condition.
    const size_t k = size_t(m_conditions.size());
    std::vector<std::vector<std::pair<double, int>>> cells(
        size_t(m_participants.size()), std::vector<std::pair<double, int>>(k, {0.0, 0}));
    for (size_t i : m_rowsOfMeasure.value(measure)) {
        const Row &row = m_rows[i];
        auto &cell = cells[size_t(m_participantIndex.value(row.participant))]
                          [size_t(m_conditionIndex.value(row.condition))];
        cell.first += row.value;
        ++cell.second;
    }
    Matrix matrix;
    for (size_t c = 0; c < k; ++c) {
        if (std::any_of(cells.begin(), cells.end(),
                        [c](const auto &row) { return row[c].second; }))
            matrix.conditions.push_back(int(c));
    }
    for (size_t p = 0; p < cells.size(); ++p) {
        std::vector<double> means;
        for (int c : matrix.conditions) {
            const auto &[sum, count] = cells[p][size_t(c)];
            if (count > 0)
                means.push_back(sum / count);
        }
        if (means.size() == matrix.conditions.size()) {
            matrix.participants.append(m_participants[int(p)]);
            matrix.rows.push_back(means);
        } else {
            matrix.incomplete.append(m_participants[int(p)]);
        }
    }
    return matrix;
}

} // namespace semhap
