#!/usr/bin/env python3
"""Taylor-Green vortex over Re = 10, 100, 300, 1000, 3000 with the transport velocity and with particle
shifting, each with and without the Laplacian correction of the shipped file, and the shipped file's
default (discretization.position_correction: auto, which picks one of the two by the cell Reynolds
number Re_h = U h / nu), as it is and without its bulk viscosity and normalised summation density.

Runs verification/taylor_green.yaml (50 x 50, or N x N with --across N) through sph-mol with --set
overrides only, collects the decay-rate error (vortex-mode fit) and L1 of every run into
OUT/re_sweep.csv and draws OUT/re_sweep.png with gnuplot. The L1 is the one at the last output time
whose exact amplitude is at least 1 % of U (t = 2 s at Re >= 100, t = 0.5 s at Re 10, where the vortex
is below the particle noise afterwards); Re 10 runs to t = 5 s to show that it stays stable. The
"signed" error is (fitted - exact) / |exact| of the decay rate: > 0 decays too slowly, < 0 too fast.

Usage: scripts/taylor_green_re_sweep.py [--across N] [--jobs J] SPH_MOL_BINARY OUT_DIR
  --across N  particles across (default 50: the shipped file)
  --jobs J    runs at a time (default 1; each run is on one thread)
Programs are started with argument lists (no shell); the gnuplot script holds only fixed text and the
fixed file names re_sweep.csv / re_sweep.png, and runs with OUT_DIR as its working directory.
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor

TRANSPORT = ["discretization.position_correction=transport_velocity"]
SHIFTING = ["discretization.position_correction=particle_shifting", "discretization.particle_shifting={coefficient: 4}"]
UNCORRECTED = ["discretization.laplacian_correction=none"]
# The file without its acoustic damping: no bulk viscosity, plain summation density (the file before
# 2026-12-06).
PLAIN = ["discretization.bulk_viscosity=0", "discretization.density=summation"]
# The shipped file corrects the Morris Laplacian (laplacian_correction: moment_symmetric); the
# *_uncorrected schemes turn the correction off. "auto" is the shipped file as it is, "auto_plain" the
# same without the bulk viscosity and the normalised summation density.
SCHEMES = {
    "transport_velocity": TRANSPORT,
    "transport_velocity_uncorrected": TRANSPORT + UNCORRECTED,
    "particle_shifting": SHIFTING,
    "particle_shifting_uncorrected": SHIFTING + UNCORRECTED,
    "auto": [],
    "auto_plain": PLAIN,
}
RES = {re_: ["fluid.kinematic_viscosity=%r" % (1.0 / re_)] for re_ in (10, 100, 300, 1000, 3000)}  # nu = U L / Re
RES[10].append("time.t_end=5")
RES[100] = []  # the shipped file


def run(binary, source, out, name, sets):
    args = [binary, "--config", os.path.join(source, "verification", "taylor_green.yaml"), "--threads", "1", "-q",
            "--overwrite", "--output", os.path.join(out, name), "--set", "output.plots=false"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    with open(os.path.join(out, name, "summary.json")) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--across", type=int, default=50, help="particles across (default 50)")
    ap.add_argument("--jobs", type=int, default=1, help="runs at a time (default 1)")
    ap.add_argument("binary")
    ap.add_argument("out")
    a = ap.parse_args()
    binary, out = os.path.abspath(a.binary), os.path.abspath(a.out)
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.makedirs(out, exist_ok=True)
    across = ["discretization.particles_across=%d" % a.across] if a.across != 50 else []
    runs = [(re_, scheme, re_sets + sets) for re_, re_sets in RES.items() for scheme, sets in SCHEMES.items()]

    def one(r):
        re_, scheme, sets = r
        s = run(binary, source, out, "re%d_%s" % (re_, scheme), across + sets)
        f = s["final_errors"]
        until = f["decay_fit_until"]
        l1 = [e["L1_velocity"] for e in s["errors"] if abs(e["t"] - until) < 1e-9][0]
        signed = (f["decay_rate"] - f["decay_rate_exact"]) / abs(f["decay_rate_exact"])
        pc = s.get("position_correction", {})
        re_h = pc.get("cell_reynolds_number", "")
        return [re_, scheme, pc.get("chosen", ""), re_h, f["decay_rate_rel_error"], signed, l1, until, f["L1_velocity_per_U"],
                s["status"]]

    with ThreadPoolExecutor(max(1, a.jobs)) as ex:
        rows = list(ex.map(one, runs))
    with open(os.path.join(out, "re_sweep.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["Re", "scheme", "chosen", "Re_h", "decay_rate_rel_error", "decay_rate_signed_error", "L1_velocity",
                    "L1_at_t [s]", "L1_velocity_per_U_at_t_end", "status"])
        w.writerows(rows)
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        print("gnuplot not found: wrote re_sweep.csv only")
        return
    script = ("""set terminal pngcairo size 1100,560
set output 're_sweep.png'
set datafile separator ','
set key autotitle columnhead
set key below font ',9'
set logscale xy
set xrange [5:5000]
set grid
set multiplot layout 1,2 title 'Taylor-Green, %d x %d: sph-mol against the exact decay'
set title 'decay-rate error (vortex-mode fit)'
set xlabel 'Re'
set ylabel 'relative error'
plot 're_sweep.csv' using 1:(strcol(2) eq 'transport_velocity' ? $5 : 1/0) with linespoints pt 7 title 'transport velocity', \\
     '' using 1:(strcol(2) eq 'transport_velocity_uncorrected' ? $5 : 1/0) with linespoints pt 6 title 'transport velocity, no Laplacian correction', \\
     '' using 1:(strcol(2) eq 'particle_shifting' ? $5 : 1/0) with linespoints pt 5 title 'particle shifting, A = 4', \\
     '' using 1:(strcol(2) eq 'particle_shifting_uncorrected' ? $5 : 1/0) with linespoints pt 4 title 'particle shifting, no Laplacian correction', \\
     '' using 1:(strcol(2) eq 'auto' ? $5 : 1/0) with points pt 2 ps 2.5 lw 2 lc rgb 'black' title 'default: position\\_correction auto', \\
     '' using 1:(strcol(2) eq 'auto_plain' ? $5 : 1/0) with points pt 1 ps 2.5 lw 2 lc rgb 'gray40' title 'default without bulk viscosity and normalised summation'
set title 'L1 velocity error / (U e^{bt})'
set ylabel 'L1'
plot 're_sweep.csv' using 1:(strcol(2) eq 'transport_velocity' ? $7 : 1/0) with linespoints pt 7 title 'transport velocity', \\
     '' using 1:(strcol(2) eq 'transport_velocity_uncorrected' ? $7 : 1/0) with linespoints pt 6 title 'transport velocity, no Laplacian correction', \\
     '' using 1:(strcol(2) eq 'particle_shifting' ? $7 : 1/0) with linespoints pt 5 title 'particle shifting, A = 4', \\
     '' using 1:(strcol(2) eq 'particle_shifting_uncorrected' ? $7 : 1/0) with linespoints pt 4 title 'particle shifting, no Laplacian correction', \\
     '' using 1:(strcol(2) eq 'auto' ? $7 : 1/0) with points pt 2 ps 2.5 lw 2 lc rgb 'black' title 'default: position\\_correction auto', \\
     '' using 1:(strcol(2) eq 'auto_plain' ? $7 : 1/0) with points pt 1 ps 2.5 lw 2 lc rgb 'gray40' title 'default without bulk viscosity and normalised summation'
unset multiplot
""" % (a.across, a.across))
    with open(os.path.join(out, "re_sweep.gp"), "w") as f:
        f.write(script)
    subprocess.run([gnuplot, "re_sweep.gp"], cwd=out, check=True)
    print("wrote", os.path.join(out, "re_sweep.csv"), "and re_sweep.png")


if __name__ == "__main__":
    main()
