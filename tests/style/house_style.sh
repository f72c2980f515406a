#!/usr/bin/env bash
# The house style is .clang-format: every C++ source of ours follows it, so a
# diff shows what changed and never how it was laid out. Lists each file that
# deviates; fix with `clang-format -i FILE`.
# Usage: house_style.sh SOURCE_DIR
set -uo pipefail
cd "$1" || exit 1
command -v clang-format >/dev/null || { echo "clang-format is missing (Debian: clang-format)"; exit 1; }
mapfile -t files < <(find app bench core tests tools ui -name '*.cpp' -o -name '*.h' | sort)
bad=()
for f in "${files[@]}"; do
    clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ "${#bad[@]}" -gt 0 ]; then
    printf 'not in the house style (clang-format -i FILE): %s\n' "${bad[@]}"
    exit 1
fi
echo "${#files[@]} files in the house style"
