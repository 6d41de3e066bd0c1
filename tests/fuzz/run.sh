#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan) and runs each for SECONDS on a working
# copy of its seed corpus, with its dictionary (spec: toml.dict and toml_structure.dict joined;
# compare and resample: png.dict). Fails on any crash, timeout (10 s per input), out-of-memory (2 GB),
# sanitizer report or leak; the input that caused it is left as BUILD/crash-*/timeout-*/oom-*
# and becomes a regression test in tests/hostile/.
#   tests/fuzz/run.sh SECONDS [HARNESS...]     (default: all; BUILD defaults to build-fuzz)
# KEEP_GOING=1 runs each harness in libFuzzer's fork mode, collecting every finding instead of
# stopping at the first (for long runs); the harness still fails if it left any.
# Every run passes libFuzzer -seed=FUZZ_SEED (default 1; printed with each harness), so that it
# mutates the same inputs in the same order: FUZZ_RUNS=N (-runs=N, which ends a harness after N
# inputs, before SECONDS if it gets there) from a fresh working corpus (rm -r BUILD/corpus-work) on
# the same build repeats a run exactly; a run bounded only by SECONDS stops wherever the machine's
# speed has got it to. Another FUZZ_SEED explores elsewhere. KEEP_GOING's fork mode is not
# repeatable. The same corpora are replayed by the ordinary test build (ctest
# "fuzz-replay:<harness>", docs/testing.md).
set -euo pipefail
seconds=${1:?usage: tests/fuzz/run.sh SECONDS [HARNESS...]}
shift
seed=${FUZZ_SEED:-1}
case $seed in '' | *[!0-9]*) echo "FUZZ_SEED must be a decimal number, not '$seed'" >&2; exit 2 ;; esac
runs=${FUZZ_RUNS:--1}
case $runs in -1) ;; '' | *[!0-9]*) echo "FUZZ_RUNS must be a decimal number, not '$runs'" >&2; exit 2 ;; esac
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
  # -reload=0: libFuzzer would otherwise reread the corpus directory every second, so that how
  # far a run had got at each second (the machine's load) would change what it mutates next.
  args=(-seed="$seed" -runs="$runs" -reload=0 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1
        -artifact_prefix="$build/$h-")
  case $h in
    spec) cat "$root/tests/fuzz/toml.dict" "$root/tests/fuzz/toml_structure.dict" >"$build/spec.dict"
          args+=(-dict="$build/spec.dict") ;;
    compare | resample) args+=(-dict="$root/tests/fuzz/png.dict") ;;
  esac
  [ "${KEEP_GOING:-0}" = 1 ] && args+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  rm -f "$build/$h-"crash-* "$build/$h-"timeout-* "$build/$h-"oom-* "$build/$h-"leak-*
  echo "== fuzz_$h for ${seconds}s, -seed=$seed"
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
