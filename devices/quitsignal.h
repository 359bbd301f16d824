// SPDX-License-Identifier: MIT
#pragma once

namespace semhap {

/**
 * A clean exit on SIGINT and SIGTERM for loops that own their devices (the emulator): the
 * handler only sets a flag the loop polls, so the loop's own clean-up runs.
 */
class QuitSignal
{
public:
    /** Installs the handlers; the flag starts cleared. */
    static void install();
    /** True once SIGINT or SIGTERM arrived. */
    static bool requested();
    /** Sets the flag as a signal would (async-signal-safe). */
    static void request();
};

} // namespace semhap
