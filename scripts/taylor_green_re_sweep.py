#!/usr/bin/env python3
"""Taylor-Green vortex over Re = 10, 100, 1000 with the transport velocity and with particle shifting,
each with and without the Laplacian correction of the shipped file.

Runs verification/taylor_green.yaml (50 x 50) through sph-mol with --set overrides only, collects the
decay-rate error (vortex-mode fit) and L1 of every run into OUT/re_sweep.csv and draws
OUT/re_sweep.png with gnuplot. The L1 is the one at the last output time whose exact amplitude is at
least 1 % of U (t = 2 s at Re 100 and 1000, t = 0.5 s at Re 10, where the vortex is below the
particle noise afterwards); Re 10 runs to t = 5 s to show that it stays stable.

Usage: scripts/taylor_green_re_sweep.py SPH_MOL_BINARY OUT_DIR
Programs are started with argument lists (no shell); the gnuplot script holds only fixed text and the
fixed file names re_sweep.csv / re_sweep.png, and runs with OUT_DIR as its working directory.
"""
import csv
import json
import os
import shutil
import subprocess
import sys

SHIFTING = ["discretization.transport_velocity.enabled=false", "discretization.particle_shifting={coefficient: 4}"]
# The shipped file corrects the Morris Laplacian (laplacian_correction: moment_symmetric); the
# *_uncorrected schemes turn the correction off.
SCHEMES = {
    "transport_velocity": [],
    "transport_velocity_uncorrected": ["discretization.laplacian_correction=none"],
    "particle_shifting": SHIFTING,
    "particle_shifting_uncorrected": SHIFTING + ["discretization.laplacian_correction=none"],
}
RES = {10: ["fluid.kinematic_viscosity=0.1", "time.t_end=5"], 100: [], 1000: ["fluid.kinematic_viscosity=0.001"]}


def run(binary, source, out, name, sets):
    args = [binary, "--config", os.path.join(source, "verification", "taylor_green.yaml"), "--threads", "1", "-q",
            "--overwrite", "--output", os.path.join(out, name), "--set", "output.plots=false"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    with open(os.path.join(out, name, "summary.json")) as f:
        return json.load(f)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    binary, out = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.makedirs(out, exist_ok=True)
    rows = []
    for re_, re_sets in RES.items():
        for scheme, sets in SCHEMES.items():
            s = run(binary, source, out, "re%d_%s" % (re_, scheme), re_sets + sets)
            f = s["final_errors"]
            until = f["decay_fit_until"]
            l1 = [e["L1_velocity"] for e in s["errors"] if abs(e["t"] - until) < 1e-9][0]
            rows.append([re_, scheme, f["decay_rate_rel_error"], l1, until, f["L1_velocity_per_U"], s["status"]])
    with open(os.path.join(out, "re_sweep.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["Re", "scheme", "decay_rate_rel_error", "L1_velocity", "L1_at_t [s]", "L1_velocity_per_U_at_t_end",
                    "status"])
        w.writerows(rows)
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("gnuplot not found: wrote re_sweep.csv only")
        return
    script = """set terminal pngcairo size 1100,450
set output 're_sweep.png'
set datafile separator ','
set key autotitle columnhead
set logscale xy
set xrange [5:2000]
set grid
set multiplot layout 1,2 title 'Taylor-Green, 50 x 50: sph-mol against the exact decay'
set title 'decay-rate error (vortex-mode fit)'
set xlabel 'Re'
set ylabel 'relative error'
plot 're_sweep.csv' using 1:(strcol(2) eq 'transport_velocity' ? $3 : 1/0) with linespoints pt 7 title 'transport velocity', \\
     '' using 1:(strcol(2) eq 'transport_velocity_uncorrected' ? $3 : 1/0) with linespoints pt 6 title 'transport velocity, no Laplacian correction', \\
     '' using 1:(strcol(2) eq 'particle_shifting' ? $3 : 1/0) with linespoints pt 5 title 'particle shifting, A = 4', \\
     '' using 1:(strcol(2) eq 'particle_shifting_uncorrected' ? $3 : 1/0) with linespoints pt 4 title 'particle shifting, no Laplacian correction'
set title 'L1 velocity error / (U e^{bt})'
set ylabel 'L1'
plot 're_sweep.csv' using 1:(strcol(2) eq 'transport_velocity' ? $4 : 1/0) with linespoints pt 7 title 'transport velocity', \\
     '' using 1:(strcol(2) eq 'transport_velocity_uncorrected' ? $4 : 1/0) with linespoints pt 6 title 'transport velocity, no Laplacian correction', \\
     '' using 1:(strcol(2) eq 'particle_shifting' ? $4 : 1/0) with linespoints pt 5 title 'particle shifting, A = 4', \\
     '' using 1:(strcol(2) eq 'particle_shifting_uncorrected' ? $4 : 1/0) with linespoints pt 4 title 'particle shifting, no Laplacian correction'
unset multiplot
"""
    with open(os.path.join(out, "re_sweep.gp"), "w") as f:
        f.write(script)
    subprocess.run([gnuplot, "re_sweep.gp"], cwd=out, check=True)
    print("wrote", os.path.join(out, "re_sweep.csv"), "and re_sweep.png")


if __name__ == "__main__":
    main()
