#!/usr/bin/env bash
# Runs one case of the robustness corpus (see README.md beside this script) and checks
# its exit code, its messages, and that it leaves nothing behind: afterwards the case's
# directory must hold exactly its own input files (no output, no temporary).
# Usage: run_case.sh GLINT_BINARY CASE   (CASE: cases/NAME.lua or cases/NAME/)
set -u
glint=$1
case_path=${2%/}
name=$(basename "$case_path")

scratch=$(mktemp -d "${TMPDIR:-/tmp}/glint-robustness.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
work="$scratch/case"
mkdir "$work"

fail() {
    echo "FAIL $name: $*"
    exit 1
}

expected_exit=""
messages=()
absent=()
environment=()
if [ -d "$case_path" ]; then
    [ -f "$case_path/case.txt" ] || fail "no case.txt"
    cp -R "$case_path"/. "$work"/
    command=""
    while IFS= read -r line || [ -n "$line" ]; do
        case "$line" in
            command:*) command=${line#command:} ;;
            expect-exit:*) expected_exit=${line#expect-exit:} ;;
            expect-message:*) messages+=("$(echo "${line#expect-message:}" | sed 's/^ //')") ;;
            expect-absent:*) absent+=("$(echo "${line#expect-absent:}" | sed 's/^ //')") ;;
            env:*) environment+=("$(echo "${line#env:}" | sed 's/^ //')") ;;
        esac
    done < "$case_path/case.txt"
    [ -n "$command" ] || fail "case.txt has no 'command:' line"
    if [ -f "$work/generate.sh" ]; then
        (cd "$work" && bash ./generate.sh) > "$scratch/generate.log" 2>&1 ||
            fail "generate.sh failed: $(cat "$scratch/generate.log")"
    fi
else
    cp "$case_path" "$work/"
    args=""
    while IFS= read -r line; do
        case "$line" in
            "-- expect-exit:"*) expected_exit=${line#-- expect-exit:} ;;
            "-- expect-message:"*) messages+=("$(echo "${line#-- expect-message:}" | sed 's/^ //')") ;;
            "-- expect-absent:"*) absent+=("$(echo "${line#-- expect-absent:}" | sed 's/^ //')") ;;
            "-- args:"*) args=${line#-- args:} ;;
            "-- env:"*) environment+=("$(echo "${line#-- env:}" | sed 's/^ //')") ;;
            --*) ;;
            *) break ;;
        esac
    done < "$case_path"
    # The defaults give way to the case's own --res or --spp (glint takes each flag once).
    defaults=""
    [[ " $args " == *" --res "* ]] || defaults+=" --res 8x8"
    [[ " $args " == *" --spp "* ]] || defaults+=" --spp 1"
    command="render $name -o out.png$defaults $args"
fi
expected_exit=$(echo "$expected_exit" | tr -d ' ')
[ -n "$expected_exit" ] || fail "no expect-exit"
[ "${#messages[@]}" -gt 0 ] || fail "no expect-message"

inputs_before=$(cd "$work" && find . -mindepth 1 | LC_ALL=C sort)
read -r -a argv <<< "$command"
(cd "$work" && env "${environment[@]}" timeout 60 "$glint" "${argv[@]}" > "$scratch/stdout" \
    2> "$scratch/stderr")
code=$?
inputs_after=$(cd "$work" && find . -mindepth 1 | LC_ALL=C sort)

status=0
if [ "$code" != "$expected_exit" ]; then
    echo "FAIL $name: exit code $code, expected $expected_exit"
    status=1
fi
for message in "${messages[@]}"; do
    if ! grep -qF -- "$message" "$scratch/stderr"; then
        echo "FAIL $name: stderr lacks '$message'"
        status=1
    fi
done
for text in "${absent[@]}"; do
    if grep -qF -- "$text" "$scratch/stderr" "$scratch/stdout"; then
        echo "FAIL $name: the output shows '$text', which it must not"
        status=1
    fi
done
if [ "$inputs_before" != "$inputs_after" ]; then
    echo "FAIL $name: files left behind or removed:"
    diff <(echo "$inputs_before") <(echo "$inputs_after") | grep '^[<>]'
    status=1
fi
if [ "$status" != 0 ]; then
    echo "command: ${environment[*]} glint $command"
    echo "--- stderr ---"
    head -c 4000 "$scratch/stderr"
    exit 1
fi
echo "ok $name"
