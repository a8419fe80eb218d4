# python/tests/sanitizer_env.sh: sourced by the scripts that run Python on
# a possibly sanitizer-instrumented libscaf.so (run_tests.sh,
# tests/install/test_install.sh).
#
# scaf_python_sanitizer_env LIB: when LIB links the AddressSanitizer /
# UndefinedBehaviorSanitizer runtimes (a SCAF_SANITIZE=ON build with gcc),
# exports LD_PRELOAD with them (an uninstrumented python must load the ASan
# runtime first) and ASAN_OPTIONS with detect_leaks=0 (LeakSanitizer would
# report the interpreter's own allocations at exit). Returns 1 when LIB is
# instrumented but its runtime cannot be preloaded (clang's static runtime,
# where __asan symbols come from the executable), 0 otherwise.
scaf_python_sanitizer_env() {
  local lib="$1" rt
  # (no grep -q: it would close the pipe early, and pipefail fail nm)
  if ! nm -D --undefined-only "$lib" 2>/dev/null | grep ' __asan_\| __ubsan_' >/dev/null; then
    return 0  # not instrumented
  fi
  rt="$(ldd "$lib" | awk '/lib(asan|ubsan)\.so/ {print $3}' | tr '\n' ' ')"
  if [ -z "${rt// /}" ]; then
    echo "$lib is sanitizer-instrumented without a shared runtime to preload: Python not run"
    return 1
  fi
  export LD_PRELOAD="$rt${LD_PRELOAD:+ $LD_PRELOAD}"
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
  return 0
}
