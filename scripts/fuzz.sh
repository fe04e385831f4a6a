#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang, AddressSanitizer and UBSan (build-fuzz/), and
# runs each for RUNS inputs (default 20000) from its seed corpus, seeded so that a run is repeatable.
#   scripts/fuzz.sh [RUNS] [TARGET ...]        e.g. scripts/fuzz.sh 1000000 fuzz_wkt   (a long session)
# New inputs go to build-fuzz/corpus/<target>/ (not the repository); a finding stops the script with
# libFuzzer's report and the input that caused it (crash-*, leak-*, timeout-*, oom-* in build-fuzz/).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-20000}
shift || true
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSYLVAROCK_FUZZ=ON -DSYLVAROCK_BUILD_TESTS=OFF \
  -DSYLVAROCK_BUILD_BENCH=OFF -DSYLVAROCK_MPI=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_targets

# Seed corpora: the hand-made test inputs (good and bad) of each format.
declare -A seeds=(
  [fuzz_inventory_stems]="tests/data/stand"
  [fuzz_inventory_plots]="tests/data/stand"
  [fuzz_points]="tests/data/stand tests/data/spatstat"
  [fuzz_wkt]="tests/fuzz/corpus/wkt"
  [fuzz_forest]="tests/fuzz/corpus/forest tests/data/stand"
  [fuzz_scene]="tests/fuzz/corpus/scene"
  [fuzz_profile]="tests/data/dem"
  [fuzz_dtm]="tests/data/dem"
  [fuzz_run_record]="tests/fuzz/corpus/run_record"
  [fuzz_campaign_store]="tests/fuzz/corpus/store"
  [fuzz_soil_types]="tests/fuzz/corpus/soil_types"
)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${!seeds[@]}")
cd build-fuzz
for t in $(printf '%s\n' "${targets[@]}" | sort); do
  mkdir -p "corpus/$t"
  dirs=()
  for d in ${seeds[$t]}; do dirs+=("../$d"); done
  echo "== $t: $runs inputs"
  # -rss_limit_mb: a reader must refuse an absurd size before it allocates (issue 13); -timeout: nor hang.
  if ! "./tests/fuzz/$t" "corpus/$t" "${dirs[@]}" -seed=1 -runs="$runs" -max_len=4096 -timeout=10 -rss_limit_mb=1024 \
      -print_final_stats=1 >"$t.log" 2>&1; then
    tail -n 60 "$t.log"
    echo "FINDING in $t: the report is above, the full log in build-fuzz/$t.log"
    exit 1
  fi
  grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units|stat::peak_rss_mb" "$t.log" | tr '\n' ' '
  echo
done
