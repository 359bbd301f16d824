// SPDX-License-Identifier: MIT
#include "mujocohandles.h"

#include <QtGlobal>

#include <mutex>

namespace semhap {

namespace {

void onWarning(const char *message)
{
    qWarning("MuJoCo: %s", message);
}

// MuJoCo carries on after the handler returns, in an undefined state: an error here is a
// bug (a loaded model has passed its checks), so stop loudly rather than simulate garbage.
void onError(const char *message)
{
    qFatal("MuJoCo error: %s", message);
}

} // namespace

void installMujocoHandlers()
{
    static std::once_flag once;
    std::call_once(once, [] {
        mju_user_warning = onWarning;
        mju_user_error = onError;
    });
}

} // namespace semhap
