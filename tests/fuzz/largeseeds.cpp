// SPDX-License-Identifier: MIT
// Writes large seeds for the fuzzers (scripts/test.sh, into the working copies of the
// corpora): an AHAP file of 5000 events and a router of 30 000 nodes, so that work growing
// faster than the input shows as a timeout. `largeseeds CONVERT_DIR ROUTER_DIR`.
#include "largeinputs.h"

#include <QFile>
#include <QJsonDocument>

#include <cstdio>

int main(int argc, char *argv[])
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: largeseeds CONVERT_DIR ROUTER_DIR\n");
        return 2;
    }
    const auto write = [](const QString &path, const QByteArray &bytes) {
        QFile file(path);
        if (file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size())
            return true;
        std::fprintf(stderr, "%s: cannot write: %s\n", qPrintable(path),
                     qPrintable(file.errorString()));
        return false;
    };
    const bool ok =
        write(QFile::decodeName(argv[1]) + QStringLiteral("/large.ahap"),
              semhap::largeAhap(5000)) &&
        write(QFile::decodeName(argv[2]) + QStringLiteral("/large.json"),
              QJsonDocument(semhap::largeRouter(30000)).toJson(QJsonDocument::Compact));
    return ok ? 0 : 1;
}
