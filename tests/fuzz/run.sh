#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer,
# and runs each for SECONDS (default 60) from the kept corpus under tests/fuzz/corpus.
# New inputs go to a scratch directory; pass --keep to add them to the kept corpus.
# Prints one line per target: executions, seconds, corpus, new inputs, and the outcome. Exits 1
# when a target crashes, hangs (more than 10 s on one input) or the sanitizers report;
# libFuzzer leaves the input as crash-*/timeout-* in the build directory.
#   usage: tests/fuzz/run.sh BUILD_DIR [SECONDS] [--keep]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:?usage: tests/fuzz/run.sh BUILD_DIR [SECONDS] [--keep]}
build=$(mkdir -p "$build" && cd "$build" && pwd)
root=$(pwd)
seconds=${2:-60}
keep=${3:-}
# The `sanitize` preset of CMakePresets.json: clang, ASan, UBSan, fuzzing coverage (CI builds
# the test suite in the same directory, so the fuzzers cost no build of their own).
cmake --preset sanitize -B "$build" > "$build.configure.log"
cmake --build "$build" --target fuzzers > "$build.build.log" 2>&1 || { tail -40 "$build.build.log"; exit 1; }
status=0
for target in $(cd tests/fuzz && ls fuzz_*.cpp | sed "s/^fuzz_//; s/\.cpp$//"); do
  corpus=$root/tests/fuzz/corpus/$target
  mkdir -p "$corpus"
  scratch=$(mktemp -d)
  new=$scratch
  [ "$keep" = "--keep" ] && new=$corpus
  log="$build/fuzz_$target.log"
  result=ok
  (cd "$build" && tests/fuzz/fuzz_$target -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 \
     -dict="$root/tests/fuzz/inputs.dict" "$new" "$corpus") > "$log" 2>&1 || { result=FAILED; status=1; }
  runs=$(grep -o "stat::number_of_executed_units: *[0-9]*" "$log" | grep -o "[0-9]*$" || echo "?")
  if [ "$keep" = "--keep" ]; then grown="kept corpus now $(ls "$new" | wc -l) inputs"; else grown="$(ls "$new" | wc -l) new inputs (not kept)"; fi
  echo "fuzz_$target: $runs executions in ${seconds} s from $(ls "$corpus" | wc -l) kept inputs, $grown, $result"
  [ "$result" = ok ] || tail -30 "$log"
  rm -rf "$scratch"
done
exit $status
