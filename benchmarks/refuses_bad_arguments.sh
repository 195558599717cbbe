#!/bin/sh
# Usage: refuses_bad_arguments.sh BENCHMARK
# An unknown option and a missing problem file each end the benchmark at once with
# status 1 and a message on stderr naming them.
benchmark="$1"
expect_refusal() {
  message="$("$benchmark" "$1" 2>&1 >/dev/null)"
  status=$?
  if [ "$status" -ne 1 ]; then echo "$benchmark $1: status $status, expected 1"; exit 1; fi
  case "$message" in
    *"$2"*) ;;
    *) echo "$benchmark $1: message '$message' does not name '$2'"; exit 1 ;;
  esac
}
expect_refusal --no-such-option "unknown option --no-such-option"
expect_refusal /no/such/problem.cfg "/no/such/problem.cfg: no such problem file"
echo "$benchmark refuses bad arguments"
