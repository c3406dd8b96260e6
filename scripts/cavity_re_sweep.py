#!/usr/bin/env python3
"""Lid-driven cavity at Re = 100, 400, 1000 against Ghia, Ghia & Shin (1982): runs sph-mol once per
Reynolds number (nu = U L / Re on verification/cavity.yaml), collects the final errors into
cavity_re_sweep.csv and plots u_rms and v_rms against Re (cavity_re_sweep.png, gnuplot).

Every program is started with an argument vector (no shell); the gnuplot script holds only numbers
and fixed file names, written by this script.

    scripts/cavity_re_sweep.py --binary build/release/sph-mol --output out/cavity_re_sweep \
        [--across 40] [--t-end 30] [--threads 1] [--dt DT] [--set key=value ...] [--reuse]
    scripts/cavity_re_sweep.py --shipped --threads 2 --output out/cavity_re_sweep  # each file as shipped
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

REYNOLDS = (100, 400, 1000)


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(here, "..", "build", "release", "sph-mol"))
    ap.add_argument("--config", default=os.path.join(here, "..", "verification", "cavity.yaml"))
    ap.add_argument("--output", default="out/cavity_re_sweep")
    ap.add_argument("--across", type=int, default=40, help="particles across the cavity")
    ap.add_argument("--t-end", type=float, default=30.0, help="simulated time [s] (L/U = 1 s)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--dt", type=float, default=None,
                    help="leapfrog step [s]; default 1e-3 * 40 / across, the shipped 0.22 h / (c + U) at every spacing")
    ap.add_argument("--set", action="append", default=[], help="further sph-mol overrides key=value")
    ap.add_argument("--shipped", action="store_true",
                    help="run the shipped files as they are, each at its own lattice, step and end time: "
                         "verification/cavity.yaml (Re 100), cavity_re400.yaml, cavity_re1000.yaml "
                         "(--config, --across, --t-end and --dt are then not used)")
    ap.add_argument("--reuse", action="store_true",
                    help="take OUTPUT/Re<N>/summary.json of an earlier run (completed, or interrupted: its last "
                         "output counts) instead of running it again")
    a = ap.parse_args()
    if a.across <= 0 or a.t_end <= 0 or a.threads <= 0:
        ap.error("--across, --t-end and --threads must be positive")
    dt = a.dt if a.dt is not None else 1e-3 * 40 / a.across
    if dt <= 0:
        ap.error("--dt must be positive")
    os.makedirs(a.output, exist_ok=True)
    # Outputs every 2 s from 10 s on: the steadiness criterion compares the last two.
    times = [t for t in range(10, int(a.t_end) + 1, 2)]
    if not times or times[-1] != a.t_end:
        times.append(a.t_end)
    rows = []
    for re in REYNOLDS:
        run_dir = os.path.join(a.output, f"Re{re}")
        args = [a.binary, "--threads", str(a.threads), "-q", "--overwrite", "--output", run_dir]
        if a.shipped:
            name = "cavity.yaml" if re == 100 else f"cavity_re{re}.yaml"
            args += ["--config", os.path.join(here, "..", "verification", name)]
        else:
            args += ["--config", a.config,
                     "--set", f"discretization.particles_across={a.across}",
                     "--set", f"fluid.kinematic_viscosity={1.0 / re!r}",
                     "--set", f"time.t_end={a.t_end!r}",
                     "--set", f"time.dt={dt!r}",
                     "--set", "output.times=[" + ", ".join(repr(float(t)) for t in times) + "]"]
        for s in a.set:
            args += ["--set", s]
        summary = os.path.join(run_dir, "summary.json")
        s = None
        if a.reuse and os.path.isfile(summary):
            with open(summary) as f:
                s = json.load(f)
            if s.get("status") not in ("completed", "interrupted") or not s.get("errors"):
                s = None
        if s is None:
            print("running Re", re, file=sys.stderr)
            subprocess.run(args, check=True)
            with open(summary) as f:
                s = json.load(f)
        e = s["final_errors"]
        spacing = s.get("discretization", {}).get("spacing")
        across = round(1.0 / spacing) if spacing else a.across  # L = 1
        rows.append((re, e["u_rms"], e["u_max"], e["v_rms"], e["v_max"], bool(e["steady"]), s["errors"][-1]["t"],
                     s.get("wall_seconds", 0.0), across))
    csv = os.path.join(a.output, "cavity_re_sweep.csv")
    with open(csv, "w") as f:
        f.write("Re [-],u_rms/U [-],u_max/U [-],v_rms/U [-],v_max/U [-],steady,t [s],wall [s],particles_across [-]\n")
        for r in rows:
            f.write(f"{r[0]},{r[1]:.6g},{r[2]:.6g},{r[3]:.6g},{r[4]:.6g},{int(r[5])},{r[6]:.6g},{r[7]:.1f},{r[8]}\n")
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("gnuplot not found: wrote", csv, "only", file=sys.stderr)
        return 0
    lattices = "/".join(f"{r[8]}" for r in rows)
    title = (f"cavity, shipped files ({lattices} across)" if a.shipped else f"cavity, {a.across} x {a.across}")
    script = (
        "set terminal pngcairo size 800,560 font ',11' noenhanced\n"
        "set output 'cavity_re_sweep.png'\n"
        "set datafile separator ','\n"
        f"set title '{title}: centre-line error vs Ghia et al. (1982), last output'\n"
        "set xlabel 'Re'\nset ylabel 'centre-line error / U'\nset logscale x\nset xrange [70:1400]\n"
        "set key top left\nset grid\n"
        "plot 'cavity_re_sweep.csv' every ::1 using 1:2 with linespoints pt 7 lw 2 title 'u_rms (x = L/2)', \\\n"
        "  '' every ::1 using 1:4 with linespoints pt 5 lw 2 title 'v_rms (y = L/2)', \\\n"
        "  '' every ::1 using 1:3 with linespoints pt 6 dt 2 title 'u_max', \\\n"
        "  '' every ::1 using 1:5 with linespoints pt 4 dt 2 title 'v_max'\n")
    with open(os.path.join(a.output, "cavity_re_sweep.gp"), "w") as f:
        f.write(script)
    subprocess.run([gnuplot, "cavity_re_sweep.gp"], cwd=a.output, check=True)
    print("wrote", csv, "and", os.path.join(a.output, "cavity_re_sweep.png"), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
