#!/usr/bin/env bash
# Builds the libFuzzer target of the C API (clang, ASan + UBSan) into ${FUZZ_BUILD_DIR:-build/fuzz}
# and runs it for FUZZ_SECONDS (default 60) from the seeds of earlier runs (its corpus directory).
# Exit 0: no crash, leak or sanitizer report; 77: clang or libFuzzer is missing (ctest: skipped).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${FUZZ_BUILD_DIR:-$root/build/fuzz}"
seconds="${FUZZ_SECONDS:-60}"
if ! command -v clang++ >/dev/null || ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
    clang++ -x c++ -fsanitize=fuzzer - -o /dev/null 2>/dev/null; then
  echo "fuzz: clang++ with libFuzzer not found (scripts/setup.sh installs clang, libclang-rt-14-dev)"
  exit 77
fi
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DEDGELIGHT_FUZZ=ON -DEDGELIGHT_BUILD_TESTS=OFF -DEDGELIGHT_BUILD_BENCHMARKS=OFF \
  -DEDGELIGHT_BUILD_TOOLS=OFF >/dev/null
cmake --build "$build" --target edgelight_fuzz_capi -j"$(nproc)"
mkdir -p "$build/corpus"
# -error_exitcode: any crash or sanitizer report fails the run; reproducers land in $build/.
cd "$build"
exec ./native/fuzz/edgelight_fuzz_capi -max_total_time="$seconds" -error_exitcode=1 -timeout=20 \
  -rss_limit_mb=2048 -print_final_stats=1 corpus
