#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) and runs each for SECONDS on a working
# copy of its seed corpus, with its dictionary (spec: toml.dict and toml_structure.dict joined;
# compare and resample: png.dict). Fails on any crash, timeout (10 s per input), out-of-memory (2 GB),
# sanitizer report or leak; the input that caused it is left as BUILD/crash-*/timeout-*/oom-*
# and becomes a regression test in tests/hostile/.
#   tests/fuzz/run.sh SECONDS [HARNESS...]     (default: all; BUILD defaults to build-fuzz)
# KEEP_GOING=1 runs each harness in libFuzzer's fork mode, collecting every finding instead of
# stopping at the first (for long runs); the harness still fails if it left any.
set -euo pipefail
seconds=${1:?usage: tests/fuzz/run.sh SECONDS [HARNESS...]}
shift
cd "$(dirname "$0")/../.."
root=$PWD
build=${BUILD:-$root/build-fuzz}
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(spec basis csv compare resample)
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER="${CXX_FUZZ:-clang++}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSPLINEFIG_FUZZ=ON -DSPLINEFIG_BUILD_TESTS=OFF >/dev/null
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build "$build" -j "${JOBS:-2}" --target "${targets[@]}" >/dev/null
status=0
for h in "${harnesses[@]}"; do
  work=$build/corpus-work/$h
  mkdir -p "$work"
  cp -n "$root/tests/fuzz/corpus/$h/"* "$work/" 2>/dev/null || true
  args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1
        -artifact_prefix="$build/$h-")
  case $h in
    spec) cat "$root/tests/fuzz/toml.dict" "$root/tests/fuzz/toml_structure.dict" >"$build/spec.dict"
          args+=(-dict="$build/spec.dict") ;;
    compare | resample) args+=(-dict="$root/tests/fuzz/png.dict") ;;
  esac
  [ "${KEEP_GOING:-0}" = 1 ] && args+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  rm -f "$build/$h-"crash-* "$build/$h-"timeout-* "$build/$h-"oom-* "$build/$h-"leak-*
  echo "== fuzz_$h for ${seconds}s"
  log=$build/fuzz_$h.log
  if ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      "$build/tests/fuzz/fuzz_$h" "${args[@]}" "$work" >"$log" 2>&1 &&
      ! compgen -G "$build/$h-*-*" >/dev/null; then
    grep -E "cov:" "$log" | tail -1 || true
    grep -E "stat::number_of_executed_units" "$log" | tail -1 || true
  else
    echo "fuzz_$h: FAILED (see $log)"; grep -E "ERROR|SUMMARY|runtime error|fuzz_$h:" "$log" | sort | uniq -c | head -10
    ls "$build/$h-"*-* 2>/dev/null | head
    status=1
  fi
done
exit $status
