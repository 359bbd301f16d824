// SPDX-License-Identifier: MIT
#pragma once

#include "liverig.h"
#include "simrun.h"

#include <QCoreApplication>
#include <QSize>
#include <QStringList>

namespace semhap {

/** How the studio starts: the run it opens and the testing hooks (`--screenshot`). */
struct StudioOptions
{
    Q_DECLARE_TR_FUNCTIONS(StudioOptions)

public:
    RunOptions run;            ///< scene, router, operator, seed; endless by default
    bool autoRun = true;       ///< start running at once (`--paused` turns it off)
    double speed = 1.0;        ///< simulated seconds per real second
    QString screenshot;        ///< grab the window to this PNG, then quit
    double quitAfter = -1.0;   ///< seconds after start to grab and quit; < 0: never
    QSize size;                ///< window size for screenshots; empty: the saved layout's
    QString language;          ///< "en", "de"; empty: the saved setting or the system's
    int posePort = 9870;       ///< UDP port of the network pose-and-grip input; 0: off
    bool live = false;         ///< `--listen`: start on a live rig instead of the scene
    LiveRigOptions liveRig;    ///< where `--listen` listens (router: `--router`)
    bool restoreLayout = true; ///< `--default-layout` ignores the saved one
    QString study;             ///< `--study`: open this study (STUDY.db) in place of the last
    QString participant;       ///< `--participant`: the study's participant to work with
    bool startStep = false;    ///< `--start-step`: start the participant's next step (tests)
    /** The command line names a run (scene, router, …): it wins over the saved workspace's. */
    bool runGiven = false;

    /**
     * Reads the command line (`args` without the program name). False with a message for
     * the user: `*help` true when it is the help or version text rather than an error.
     */
    static bool parse(const QStringList &args, StudioOptions *options, QString *message,
                      bool *help);
};

} // namespace semhap
