#!/usr/bin/env bash
# Strong and weak scaling of sph-mol under mpirun: per rank count, the wall time per particle-step
# (and the RHS and search time alone, without set-up and output),
# each rank's pair work (owned rows and redundant halo rows), halo size, seconds in exchanges and
# the load imbalance, from the run summaries' `parallel` object; and the communication share
# extrapolated to more ranks from the measured halo volumes (the model is printed with the table).
#
#   scripts/bench_mpi.sh [--binary build/mpi/sph-mol] [--config verification/dam_break.yaml]
#                        [--ranks "1 2"] [--spacing 0.01] [--t-end 0.005] [--weak [--unit 1]]
#                        [--model-ranks "4 16 64"] [--model-from R] [--output out/bench_mpi] [--set key=value ...]
#
# Strong scaling (default): the same scene on every rank count. --weak: the spacing shrinks as
# ranks^(-1/D), so that the particles per rank stay about the same, rounded so that --unit (a length
# the scene needs to be a whole number of spacings, e.g. 1 m for the dam break's column) stays
# whole. One OpenMP thread per rank.
# Writes bench_mpi.csv (one row per rank count) and model.csv (the extrapolation) in the output
# folder and prints both. The model is fitted to the run on --model-from ranks (default: the most
# ranks measured that do not exceed the machine's cores; oversubscribed ranks mostly wait). Needs
# mpirun and python3.
set -euo pipefail

binary=build/mpi/sph-mol
config=verification/dam_break.yaml
ranks="1 2"
spacing=0.01
t_end=0.005
weak=0
unit=""
model_ranks="4 16 64"
model_from=""
output=out/bench_mpi
sets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --binary) binary="$2"; shift 2 ;;
    --config) config="$2"; shift 2 ;;
    --ranks) ranks="$2"; shift 2 ;;
    --spacing) spacing="$2"; shift 2 ;;
    --t-end) t_end="$2"; shift 2 ;;
    --weak) weak=1; shift ;;
    --unit) unit="$2"; shift 2 ;;
    --model-ranks) model_ranks="$2"; shift 2 ;;
    --model-from) model_from="$2"; shift 2 ;;
    --output) output="$2"; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) echo "bench_mpi.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ -x "$binary" ]] || { echo "bench_mpi.sh: no executable '$binary' (build with -DSPHMOL_MPI=ON)" >&2; exit 2; }
[[ -f "$config" ]] || { echo "bench_mpi.sh: no config '$config'" >&2; exit 2; }
command -v mpirun >/dev/null || { echo "bench_mpi.sh: mpirun not found" >&2; exit 2; }
mkdir -p "$output"

dimension=$(python3 - "$config" <<'EOF'
import re, sys
for line in open(sys.argv[1]):
    m = re.match(r"\s*dimension:\s*(\d)", line)
    if m:
        print(m.group(1)); break
else:
    print(2)
EOF
)

mpi_args=(--oversubscribe)
[[ $EUID -eq 0 ]] && mpi_args+=(--allow-run-as-root)  # Open MPI refuses root unless told (containers, CI)
for r in $ranks; do
  dx=$spacing
  if [[ $weak -eq 1 ]]; then
    dx=$(python3 - "$spacing" "$r" "$dimension" "$unit" <<'EOF'
import sys
dx, r, dim, unit = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
dx *= r ** (-1.0 / dim)
if unit:
    dx = float(unit) / round(float(unit) / dx)
print(repr(dx))
EOF
)
  fi
  run_dir="$output/ranks_$r"
  echo "== $r rank(s), spacing $dx" >&2
  # Arguments go to mpirun and sph-mol as an array: no shell parses them. The log is created anew
  # (noclobber: O_EXCL), never written through a symlink left in its place.
  rm -f "$output/ranks_$r.log"
  set -o noclobber
  OMP_NUM_THREADS=1 mpirun "${mpi_args[@]}" -n "$r" "$binary" --threads 1 --config "$config" --output "$run_dir" --overwrite \
    --set "discretization.spacing=$dx" --set "time.t_end=$t_end" --set "output.times=[$t_end]" \
    --set output.plots=false "${sets[@]}" >"$output/ranks_$r.log" 2>&1 ||
    { echo "bench_mpi.sh: the run on $r rank(s) failed; see $output/ranks_$r.log" >&2; exit 1; }
  set +o noclobber
done

if [[ -z "$model_from" ]]; then
  model_from=0
  # The machine's cores (those this process may run on): GNU nproc reports OMP_NUM_THREADS instead
  # when that is set, and a shell with OMP_NUM_THREADS=1 then fits no model.
  cores=$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)
  for r in $ranks; do if [[ $r -gt 1 && $r -le $cores ]]; then model_from=$r; fi; done
fi
python3 - "$output" "$dimension" "$model_ranks" "$model_from" $ranks <<'EOF'
import csv, json, math, os, sys, tempfile


def write_csv(path, rows):
    """The table into a new temporary file beside `path`, then renamed over it: an existing file or
    symlink at `path` is replaced, never written through."""
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".bench_mpi.", suffix=".csv")
    try:
        with os.fdopen(fd, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


out, dim, model_ranks, model_from = sys.argv[1], int(sys.argv[2]), [int(x) for x in sys.argv[3].split()], int(sys.argv[4])
ranks = [int(x) for x in sys.argv[5:]]
rows = []
for r in ranks:
    s = json.load(open(os.path.join(out, f"ranks_{r}", "summary.json")))
    n = s["particles_total"]
    steps = s["steps"]
    evals = s["rhs_evals"]
    p = s.get("parallel", {})
    owned = p.get("owned_particles", [n])
    halo = p.get("halo_particles_max", [0])
    pairs = p.get("verlet_pairs_owned_rows", [0])
    redundant = p.get("verlet_pairs_halo_rows", [0])
    exchange = p.get("exchange_seconds", [0.0])
    rhs = p.get("rhs_seconds", [s["wall_seconds"]])
    rows.append({
        "ranks": r,
        "particles": n,
        "steps": steps,
        "rhs_evals": evals,
        "wall_s": s["wall_seconds"],
        # The RHS and the neighbour search alone (rank 0's): the set-up, the partition and the output
        # gathers left out, which a short benchmark run would otherwise be dominated by.
        "rhs_search_s": s["wall_seconds_breakdown"].get("rhs_without_search", 0.0) + s["wall_seconds_breakdown"].get("neighbour_search", 0.0),
        "us_per_particle_step": 1e6 * s["wall_seconds"] / (n * steps),
        "owned_max": max(owned),
        "halo_max": max(halo),
        "halo_share": max(h / o for h, o in zip(halo, owned)) if r > 1 else 0.0,
        "pairs_owned_max": max(pairs),
        "pairs_halo_rows_max": max(redundant),
        "redundant_pair_share": (max(x / max(y, 1) for x, y in zip(redundant, pairs)) if r > 1 else 0.0),
        "imbalance": p.get("load_imbalance", 1.0),
        "exchange_s_max": max(exchange),
        "rhs_s_max": max(rhs),
        "exchange_share": max(e / max(t, 1e-300) for e, t in zip(exchange, rhs)) if r > 1 else 0.0,
    })
base = rows[0]
for row in rows:  # particle-steps per second against the first rank count's
    row["speedup_vs_first"] = base["us_per_particle_step"] / row["us_per_particle_step"]
    row["rhs_speedup_vs_first"] = (base["rhs_search_s"] / (base["particles"] * base["steps"])) / (
        row["rhs_search_s"] / (row["particles"] * row["steps"]))
write_csv(os.path.join(out, "bench_mpi.csv"), rows)

# Model. Recursive bisection cuts a D-dimensional domain into boxes of N/P particles; a box's halo
# is a shell one halo depth thick on its cut faces, so a rank's halo scales as (N/P)^((D-1)/D)
# (fitted to the run on P = --model-from ranks: h = c (N/P)^((D-1)/D)). Per evaluation a rank sends and
# receives its halo's fields; the exchange time per halo particle, t_x, is taken from the same run
# (its exchange seconds, which include waiting for the slower rank, per evaluation and halo
# particle), and the compute time per owned pair row from its RHS seconds less the exchange. The
# communication share at P ranks is then t_x h / (t_x h + t_c pairs(N/P)). The model ignores
# latency growth with the number of neighbours (RCB boxes have up to 2 D neighbours in the bulk
# against 1 for the two-rank cut), so it is a lower bound for the share at large P.
multi = [r for r in rows if r["ranks"] == model_from and model_from > 1]
model = []
if multi:
    m = multi[0]
    P, N = m["ranks"], m["particles"]
    per_rank = N / P
    c = m["halo_max"] / per_rank ** ((dim - 1) / dim)
    evals = m["rhs_evals"]
    t_x = m["exchange_s_max"] / (evals * max(m["halo_max"], 1))
    pairs_per_particle = m["pairs_owned_max"] / max(m["owned_max"], 1)
    t_c = (m["rhs_s_max"] - m["exchange_s_max"]) / (evals * max(m["pairs_owned_max"], 1))
    for q in sorted(set(model_ranks + [P])):
        for n_total in sorted({N, N * q // P}):
            local = n_total / q
            h = c * local ** ((dim - 1) / dim)
            comm = t_x * h
            comp = t_c * pairs_per_particle * local
            model.append({"ranks": q, "particles": int(n_total), "scaling": "strong" if n_total == N else "weak",
                          "halo_per_rank": h, "halo_share": h / local, "comm_share": comm / (comm + comp)})
    write_csv(os.path.join(out, "model.csv"), model)

def table(rs, keys):
    print(" | ".join(keys))
    for r in rs:
        print(" | ".join(f"{r[k]:.4g}" if isinstance(r[k], float) else str(r[k]) for k in keys))

table(rows, ["ranks", "particles", "steps", "wall_s", "us_per_particle_step", "speedup_vs_first", "rhs_search_s",
             "rhs_speedup_vs_first", "halo_max", "halo_share",
             "redundant_pair_share", "imbalance", "exchange_share"])
if model:
    print()
    print(f"model: halo = {c:.3g} (N/P)^({dim - 1}/{dim}); exchange {t_x * 1e9:.3g} ns per halo particle and evaluation; "
          f"compute {t_c * 1e9:.3g} ns per owned pair (from the {P}-rank run)")
    table(model, ["ranks", "particles", "scaling", "halo_per_rank", "halo_share", "comm_share"])
EOF
