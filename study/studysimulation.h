// SPDX-License-Identifier: MIT
#pragma once

#include "personparameters.h"
#include "studydatabase.h"

#include <QString>

#include <cstdint>
#include <functional>

namespace semhap {

/**
 * A study run headless with simulated participants (`semhap study simulate`,
 * docs/studies.md): each participant, added in turn, takes their order of conditions and
 * does every practice round and trial the protocol asks with the reactive (or the
 * perceiving) operator, each
 * recorded into a session and entered into the study as a real one would be. The
 * questionnaires are left unanswered: nothing simulates what a person thinks.
 */
class StudySimulation
{
public:
    struct Options
    {
        /** The whole study's participants, in every shard. */
        int participants = 20;
        /**
         * Which of them this run simulates: participant n (1-based) when (n - 1) % shards ==
         * shard - 1, so that the shards 1..shards together are the whole study.
         */
        int shard = 1;
        int shards = 1;
        /**
         * Goes on with a study this simulation began: the practice rounds and trials done
         * stay, the rest (one a kill cut off included) run.
         */
        bool resume = false;
        /** Caps every practice round and trial (simulated s); 0: the protocol's lengths. */
        double maxSeconds = 0.0;
        /** The participants' operator: one of operatorNames(). */
        QString operatorName = QStringLiteral("reactive");
        /** The perceiving operator's person. */
        PersonParameters person;
        /** Asked between physics steps; true ends the simulation (the trial aborted). */
        std::function<bool()> cancelled;
        /** Told of each practice round and trial once it is entered into the study. */
        std::function<void(const StudyDatabase::Trial &)> progress;
    };

    /**
     * The seed of a participant's run: from their number (1-based) and the trial (0 for the
     * practice round), the same for every condition, so conditions meet the same cubes and
     * the same operator noise, as the seeds of `semhap compare` do.
     */
    static std::uint64_t seed(int participant, int trial);
    /** Participant `number`'s name (P01 …) in a study of `participants`. */
    static QString participantName(int number, int participants);
    /** The operators a study simulates participants with: those that heed feedback. */
    static QStringList operatorNames();
    /** The longest a practice round runs when its goal is a number of transfers only (s). */
    static constexpr double PracticeLimit = 600.0;

    /**
     * Adds this shard's participants of `options.participants` (P01, P02, …; all of them
     * with one shard) to a study that has none and runs their steps; resumed, runs only the
     * steps not done, adding those of the participants it lacks. False with `error` (`FILE:
     * reason`) when a run or a write failed or the simulation was cancelled.
     */
    static bool run(StudyDatabase &study, const Options &options, QString *error);
};

} // namespace semhap
