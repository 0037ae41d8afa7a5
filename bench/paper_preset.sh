#!/usr/bin/env bash
# Wall time and missions per second of an experiment preset run by the CLI — by default the
# issue's benchmark: the full `paper` preset (12 000 missions) with --jobs 2.
#
#   bench/paper_preset.sh [--preset NAME] [--jobs N] [--cli PATH] [--keep] [-- EXPERIMENT ARGS...]
#
# Example (only the planners merged so far): bench/paper_preset.sh --preset paper-quick -- \
#   --algorithms lawnmower
# Prints wall time, missions/s, the CPU time of the command (user + sys: what the missions cost
# without the other load on the machine) and the load average; the results go to a temporary
# directory that is removed afterwards unless --keep is given.
set -euo pipefail

here=$(cd "$(dirname "$0")/.." && pwd)
preset=paper
jobs=2
cli="$here/build/release/hullinspect"
keep=0
extra=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --preset) preset=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --cli) cli=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    --) shift; extra=("$@"); break ;;
    *) echo "usage: $0 [--preset NAME] [--jobs N] [--cli PATH] [--keep] [-- ARGS...]" >&2; exit 2 ;;
  esac
done
[[ -x "$cli" ]] || { echo "$cli not found: build it with cmake --build build/release --target hullinspect" >&2; exit 2; }

work=$(mktemp -d)
if [[ $keep -eq 0 ]]; then trap 'rm -rf "$work"' EXIT; fi
out="$work/results"

load_before=$(cut -d' ' -f1 /proc/loadavg)
start=$(date +%s.%N)
/usr/bin/time -f "%U %S" -o "$work/cpu" \
  "$cli" experiment --preset "$preset" --jobs "$jobs" --out "$out" "${extra[@]}" >"$work/stdout" 2>"$work/stderr" || {
  cat "$work/stderr" >&2; exit 1; }
end=$(date +%s.%N)
load_after=$(cut -d' ' -f1 /proc/loadavg)

runs=$(( $(wc -l <"$out/runs.csv") - 1 ))
incomplete=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "complete") c = i; next }
                      $c != "1" { n++ } END { print n + 0 }' "$out/runs.csv")
/usr/bin/python3 - "$out" "$start" "$end" "$runs" "$incomplete" "$preset" "$jobs" "$(cat "$work/cpu")" \
    "$load_before $load_after" "${extra[*]:-}" <<'PY'
import json, sys, os
out, start, end, runs, incomplete, preset, jobs, cpu, load, extra = sys.argv[1:11]
wall = float(end) - float(start)
cpu_seconds = sum(float(x) for x in cpu.split())
m = json.load(open(os.path.join(out, "manifest.json")))
inv = m.get("last_invocation", {})
print(f"preset             {preset} {extra}".rstrip())
print(f"git revision       {m.get('git_revision')}")
print(f"host cores         {m['host']['cores']}   jobs {jobs}")
print(f"missions           {runs} ({incomplete} incomplete)")
print(f"wall time          {wall:.2f} s (whole command: config, runs, final tables)")
print(f"missions/s         {int(runs) / wall:.1f} (whole command)")
print(f"CPU time           {cpu_seconds:.2f} s user+sys ({cpu_seconds / wall:.2f} cores busy on average)")
print(f"load average       {load.split()[0]} before, {load.split()[1]} after (1 min)")
print(f"runner             {inv.get('seconds', 0):.2f} s, {inv.get('missions_per_second', 0):.1f} missions/s, "
      f"{inv.get('partitions_computed', 0)} partitions computed")
PY
if [[ $keep -eq 1 ]]; then echo "results kept in $out"; fi
