# Sourced by the command-line tests: a count of failures and the checks
# that add to it. A script ends with `[ "$failures" = 0 ]`-style reporting.
failures=0

# fail MESSAGE: one more failure, said on stderr.
fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# expect STATUS COMMAND...: runs the command, its stdout in out.txt, its stderr in err.txt.
expect() {
    local want=$1
    shift
    "$@" >out.txt 2>err.txt
    local got=$?
    [ "$got" = "$want" ] || fail "exit $got, wanted $want: $* ($(head -c 300 err.txt))"
}

# expect_message TEXT: the last command's stderr says TEXT.
expect_message() {
    grep -q -- "$1" err.txt || fail "no message '$1' in: $(head -c 300 err.txt)"
}

# Sourced as `source expect.sh "$@"` by a test run as TEST JLADDER
# [SOURCE_DIR] WORK_DIR: sets $jladder, $source (when given) and $work,
# and runs the rest in an empty $work.
if [ $# -ge 2 ]; then
    jladder=$1
    work=${!#}
    if [ $# -ge 3 ]; then source=$2; fi
    rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fi
