#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The paper's three studies simulated with the perceiving operator (docs/replication.md).

  scripts/replicate.py OUTDIR [--participants 20] [--seconds 60] [--jobs 2]
  scripts/replicate.py OUTDIR --sensitivity [--participants 8] [--seconds 60] [--jobs 2]
                       [--studies bimanual,...] [--parameters NAME,...]

Runs `semhap study simulate` on resources/studies/{comparison,unimanual,bimanual}.json into
OUTDIR (a study already there is kept: a run cut off is resumed by deleting only its file),
then prints, as Markdown, each task-performance effect the paper reports as significant
beside the simulated direction and test, and the count of agreements. With --sensitivity,
it does the same with each of the person's parameters at both ends of its range, one at a
time (an end that is the default reuses the defaults' studies; only the studies' measures are
kept, not their sessions), and prints which verdicts hold and which flip, in the order of
--parameters. It prints the wall time it took.
"""

import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STUDIES = ("comparison", "unimanual", "bimanual")

# The task-performance effects the paper reports as significant (its sections 5-7), each
# with the direction it reports, whole: "semantic fewest" is fewer than each of the other
# three. `lower` and `higher` list pairs (a, b): the paper's mean of a is below (above) b's.
# An interaction has no direction in the paper: only its test counts.
EFFECTS = [
    {"study": "comparison", "measure": "average_grasp_force", "effect": "grasp:break",
     "paper": "Grasp × Break interaction, F(1, 11) = 5.65, p = .037 (no pair differs)"},
    {"study": "unimanual", "measure": "average_grasp_force",
     "higher": [("none", "visual"), ("none", "sensory")],
     "paper": "none (46.6 N) above visual (42.7 N) and sensory (41.6 N); "
              "F(3, 33) = 11.67, p < .001"},
    {"study": "bimanual", "measure": "cubes_broken",
     "lower": [("semantic", "none"), ("semantic", "visual"), ("semantic", "sensory")],
     "paper": "semantic fewest (7.40), none (10.70) and sensory (10.35) most; "
              "χ²(3) = 12.17, p = .007"},
    {"study": "bimanual", "measure": "containers_dropped",
     "lower": [("semantic", "none"), ("semantic", "visual"), ("semantic", "sensory")],
     "higher": [("sensory", "none"), ("sensory", "visual")],
     "paper": "semantic fewest (3.35), sensory most (5.80); χ²(3) = 10.27, p = .016"},
]
ALPHA = 0.05


def simulate(semhap, study, out, participants, seconds, person, only_measures):
    if os.path.exists(out):
        return out
    args = [semhap, "study", "simulate", os.path.join(ROOT, "resources", "studies", study + ".json"),
            "--participants", str(participants), "--out", out, "--trial-seconds", str(seconds),
            "--operator", "perceiving"]
    for assignment in person:
        args += ["--person", assignment]
    done = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        # A study cut off is not kept: it would be read as a whole one.
        for path in (out, out[:-3] + ".sessions"):
            subprocess.run(["rm", "-rf", path])
        sys.exit(f"{out}: {done.stderr.strip()}")
    if only_measures:
        # A sensitivity run needs the measures only; its sessions (1.4 GB for a bimanual
        # study of 8) would fill a disk over forty runs.
        subprocess.run(["rm", "-rf", out[:-3] + ".sessions"])
    return out


def analyze(semhap, db):
    done = subprocess.run([semhap, "study", "analyze", db, "--json"], capture_output=True,
                          text=True, check=True)
    return {m["measure"]: m for m in json.loads(done.stdout)["measures"]}


def p_text(p):
    return "p < .001" if p < 0.001 else f"p = {p:.3f}".replace("0.", ".", 1)


def test_text(measure, effect=None):
    if effect:
        a = measure["two_way_anova"][effect]
        return a["p"], f"F({a['df1']:g}, {a['df2']:g}) = {a['f']:.2f}, {p_text(a['p'])}"
    if measure["primary"] == "anova":
        a = measure["anova"]
        if a["mauchly"]["tested"] and a["mauchly"]["p"] < ALPHA:
            # Sphericity rejected: the Greenhouse-Geisser correction is the test, as in the report.
            g = a["greenhouse_geisser"]
            return g["p"], (f"RM-ANOVA F({g['df1']:.2f}, {g['df2']:.2f}) = {a['f']:.2f}, "
                            f"{p_text(g['p'])} (Greenhouse–Geisser)")
        return a["p"], f"RM-ANOVA F({a['df1']:g}, {a['df2']:g}) = {a['f']:.2f}, {p_text(a['p'])}"
    f = measure["friedman"]
    return f["p"], f"Friedman χ²({f['df']:g}) = {f['chi_squared']:.2f}, {p_text(f['p'])}"


def order(means):
    """The conditions from the lowest mean to the highest: `visual < semantic = none`."""
    ranked = sorted(means, key=lambda c: means[c])
    text = ranked[0]
    for before, after in zip(ranked, ranked[1:]):
        text += (" = " if means[after] == means[before] else " < ") + after
    return text


def judge(effect, measures):
    """The simulated direction and test of one effect, and whether it agrees."""
    m = measures[effect["measure"]]
    means = {c["condition"]: c["mean"] for c in m["conditions"]}
    p, text = test_text(m, effect.get("effect"))
    if "effect" in effect:
        return "—", text, p < ALPHA
    pairs = [(a, b, "<") for a, b in effect.get("lower", [])] + \
            [(a, b, ">") for a, b in effect.get("higher", [])]
    def compared(a, b):
        sign = "<" if means[a] < means[b] else ">" if means[a] > means[b] else "="
        return f"{a} {means[a]:.2f} {sign} {b} {means[b]:.2f}"
    shown = ", ".join(compared(a, b) for a, b, _ in pairs)
    same = all((means[a] < means[b]) if sign == "<" else (means[a] > means[b]) for a, b, sign in pairs)
    return shown, text, same and p < ALPHA


def agreement(semhap, dbs, effects):
    measures = {study: analyze(semhap, db) for study, db in dbs.items()}
    rows = []
    for effect in effects:
        direction, text, agrees = judge(effect, measures[effect["study"]])
        rows.append((effect, direction, text, agrees))
    return rows


def parameters(semhap):
    """The person's parameters, each with its range and its default, as semhap states them."""
    base = [semhap, "run", "--scene", "box_and_block", "--router", "none", "--operator",
            "perceiving", "--duration", "1", "--person"]
    probe = subprocess.run(base + ["?"], capture_output=True, text=True)
    names = re.search(r"NAME one of (.*)", probe.stderr).group(1).strip().split(", ")
    ranges = {}
    for name in names:
        probe = subprocess.run(base + [f"{name}=1e300"], capture_output=True,
                               text=True)
        ranges[name] = re.search(r"from (\S+) to ([0-9.e+-]+).*\(default (\S+)\)",
                                 probe.stderr).groups()
    return ranges


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out")
    parser.add_argument("--semhap", default=os.path.join(ROOT, "build", "cli", "semhap"))
    parser.add_argument("--participants", type=int)
    parser.add_argument("--seconds", type=float, default=60)
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--sensitivity", action="store_true")
    parser.add_argument("--studies", default=",".join(STUDIES),
                        help="the studies to run (their effects only are judged)")
    parser.add_argument("--parameters", help="--sensitivity: only these parameters")
    options = parser.parse_args()
    participants = options.participants or (8 if options.sensitivity else 20)
    os.makedirs(options.out, exist_ok=True)
    start = time.monotonic()

    studies = [s for s in STUDIES if s in options.studies.split(",")]
    effects = [e for e in EFFECTS if e["study"] in studies]
    settings = [("defaults", [])]
    same = {}  # a range end that is the default: its studies are the defaults' own
    if options.sensitivity:
        ranges = parameters(options.semhap)
        names = options.parameters.split(",") if options.parameters else list(ranges)
        for name in names:
            if name not in ranges:
                sys.exit(f"--parameters: {name}: not a parameter; one of {', '.join(ranges)}")
            low, high, default = ranges[name]
            for end in (low, high):
                settings.append((f"{name}={end}", [f"{name}={end}"]))
                if float(end) == float(default):
                    same[settings[-1][0]] = "defaults"
    jobs = {}
    with concurrent.futures.ThreadPoolExecutor(options.jobs) as pool:
        for label, person in settings:
            if label in same:
                continue
            tag = re.sub(r"[^a-z0-9_.]+", "-", label)
            for study in studies:
                db = os.path.join(options.out, f"{study}-{participants}-{tag}.db")
                jobs[(label, study)] = pool.submit(simulate, options.semhap, study, db,
                                                   participants, options.seconds, person,
                                                   options.sensitivity)
        dbs = {key: job.result() for key, job in jobs.items()}
    for label, twin in same.items():
        for study in studies:
            dbs[(label, study)] = dbs[(twin, study)]

    base = agreement(options.semhap, {s: dbs[("defaults", s)] for s in studies}, effects)
    print(f"## Agreement: {participants} participants, trials capped at {options.seconds:g} s\n")
    print("| study | measure | the paper | simulated direction | simulated test | agrees |")
    print("|---|---|---|---|---|---|")
    for effect, direction, text, agrees in base:
        print(f"| {effect['study']} | `{effect['measure']}`"
              f"{' (' + effect['effect'] + ')' if 'effect' in effect else ''} | {effect['paper']} "
              f"| {direction} | {text} | {'yes' if agrees else 'no'} |")
    print(f"\n{sum(row[3] for row in base)} of {len(base)} effects agree.\n")

    if options.sensitivity:
        print("## Sensitivity: each parameter at both ends of its range\n")
        header = " | ".join(f"{e['study']} `{e['measure']}`" for e in effects)
        print(f"| setting | {header} | agree |")
        print("|---|" + "---|" * len(effects) + "---|")
        for label, _ in settings:
            rows = agreement(options.semhap, {s: dbs[(label, s)] for s in studies}, effects)
            cells = []
            measures = {s: analyze(options.semhap, dbs[(label, s)]) for s in studies}
            for (effect, _, text, agrees), (_, _, _, was) in zip(rows, base):
                verdict = "agrees" if agrees else "no"
                means = {c["condition"]: c["mean"]
                         for c in measures[effect["study"]][effect["measure"]]["conditions"]}
                cells.append(verdict + (" (flips)" if agrees != was else "") +
                             f": {order(means)}; {text}")
            shown = label + (" (the default)" if label in same else "")
            print(f"| {shown} | " + " | ".join(cells) + f" | {sum(r[3] for r in rows)} |")
    print(f"\nWall time: {time.monotonic() - start:.0f} s with {options.jobs} jobs.")


if __name__ == "__main__":
    main()
