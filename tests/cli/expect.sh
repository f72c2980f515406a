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
