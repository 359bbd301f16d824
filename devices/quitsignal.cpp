// SPDX-License-Identifier: MIT
#include "quitsignal.h"

#include <atomic>
#include <csignal>

namespace semhap {

namespace {

std::atomic<bool> g_quit{false};

extern "C" void onQuitSignal(int)
{
    QuitSignal::request();
}

} // namespace

void QuitSignal::install()
{
    g_quit.store(false);
    std::signal(SIGINT, onQuitSignal);
    std::signal(SIGTERM, onQuitSignal);
}

bool QuitSignal::requested()
{
    return g_quit.load();
}

void QuitSignal::request()
{
    g_quit.store(true);
}

} // namespace semhap
