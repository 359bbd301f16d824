// SPDX-License-Identifier: MIT
#include "runsource.h"

#include "routercontext.h"
#include "sessioninfo.h"

#include <chrono>
#include <thread>

namespace semhap {

void RunSource::wait(int msecs)
{
    std::this_thread::sleep_for(std::chrono::milliseconds(msecs));
}

RouterContext RunSource::routerContext(double reactionTime) const
{
    RouterContext context;
    context.reactionTime = reactionTime;
    return context;
}

SessionInfo RunSource::sessionInfo() const
{
    return SessionInfo();
}

} // namespace semhap
