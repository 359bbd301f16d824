// SPDX-License-Identifier: MIT
#include "bandstatelog.h"

#include "jsonlineswriter.h"

#include <cmath>

namespace semhap {

namespace {

void appendArray(QByteArray &line, const std::vector<double> &values)
{
    line += '[';
    for (size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            line += ',';
        JsonLinesWriter::appendNumber(line, std::round(values[i] * 1e4) / 1e4);
    }
    line += ']';
}

} // namespace

bool BandStateLog::open(const QString &path, QString *error)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = QStringLiteral("%1: cannot write: %2").arg(path, m_file.errorString());
        return false;
    }
    return true;
}

bool BandStateLog::write(double t, const std::vector<double> &setpoints,
                         const std::vector<double> &values)
{
    if (!m_file.isOpen())
        return m_error.isEmpty();
    m_state.resize(0);
    appendArray(m_state, setpoints);
    m_state += ", \"values\": ";
    appendArray(m_state, values);
    if (m_state == m_lastState)
        return true;
    m_lastState.swap(m_state);
    m_line = "{\"t\": ";
    JsonLinesWriter::appendNumber(m_line, t);
    m_line += ", \"setpoint\": " + m_lastState + "}\n";
    // Written and flushed line by line; a full disk ends the band's run.
    if (m_file.write(m_line) != m_line.size() || !m_file.flush()) {
        m_error =
            QStringLiteral("%1: cannot write: %2").arg(m_file.fileName(), m_file.errorString());
        m_file.close();
        return false;
    }
    return true;
}

} // namespace semhap
