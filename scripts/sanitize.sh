#!/usr/bin/env bash
# The sanitizer and fuzzing stage (docs/fuzzing.md; CI runs it after scripts/test.sh):
# clang builds the fast unit tests and the libFuzzer targets of the readers of user input
# with AddressSanitizer and UndefinedBehaviorSanitizer in build_sanitize/, then runs the
# fast tests there and each fuzz target for FUZZ_SECONDS (default 20) over its corpus.
# CI's short runs start from a fixed seed (FUZZ_SEED, default 1): the same code explores
# the same inputs in every CI run, and a finding replays. The long runs take FUZZ_SEED=0
# (a random seed each run), to find what the fixed seed does not reach.
#   FUZZ_SECONDS=600 FUZZ_SEED=0 SANITIZE_HEAVY=1 bash scripts/sanitize.sh     the long runs
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh clang libclang-rt-14-dev
fuzzers=(fuzz_gmsh_mesh fuzz_surface_mesh fuzz_body_file fuzz_fmu_description fuzz_case_file)
unit_tests=(test_common test_mbs test_sph test_coupling)
# -O1, as the sanitizers' authors advise: the build takes about two thirds of -O3's time
# (the stage's largest part on 2 cores) and the checks find the same faults.
CC=clang CXX=clang++ cmake -S . -B build_sanitize -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DCHIPFLEX_FUZZ=ON -DCHIPFLEX_NATIVE=OFF > /dev/null
cmake --build build_sanitize -j"$(nproc)" --target "${fuzzers[@]}" "${unit_tests[@]}"
cd build_sanitize
export LSAN_OPTIONS="suppressions=$PWD/../tests/fuzz/lsan.supp"
# The fast unit tests: Catch2's [validation] cases are the long runs, and the [heavy] ones
# take 10-110 s each under the sanitizers (about 4.5 of the 6 minutes all of them take; the
# same code paths have shorter cases here). SANITIZE_HEAVY=1 runs them too.
spec="~[validation]~[heavy]"
[ "${SANITIZE_HEAVY:-0}" = 1 ] && spec="~[validation]"
for t in "${unit_tests[@]}"; do
  echo "== $t (AddressSanitizer, UndefinedBehaviorSanitizer)"
  OMP_NUM_THREADS=2 "bin/$t" "$spec" | tail -2
done
seconds=${FUZZ_SECONDS:-20}
for f in "${fuzzers[@]}"; do
  target=${f#fuzz_}
  corpus=$(mktemp -d)
  cp ../tests/fuzz/corpus/"$target"/* "$corpus"/
  dict=()
  [ -f ../tests/fuzz/"$target".dict ] && dict=(-dict=../tests/fuzz/"$target".dict)
  echo "== $f for $seconds s"
  log=$(mktemp)
  if ! "bin/$f" -max_total_time="$seconds" -seed="${FUZZ_SEED:-1}" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 \
    "${dict[@]}" "$corpus" > "$log" 2>&1; then
    tail -40 "$log"
    echo "FAIL: $f found a crash, a hang, a leak or an out-of-memory (the input: build_sanitize/crash-*, leak-*, timeout-* or oom-*)"
    exit 1
  fi
  grep -E "^#[0-9]+[[:space:]]+DONE" "$log"
  rm -f "$log"
  rm -rf "$corpus"
done
