// SPDX-License-Identifier: MIT
// `--set NODE.PARAM=VALUE` overrides on the C3 preset: applied and compiled, never a crash.
#include "router.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString assignment =
        QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    semhap::LoadError error;
    semhap::loadRouter(QStringLiteral("C3"), {assignment}, &error);
    return 0;
}
