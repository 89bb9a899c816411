# SPDX-License-Identifier: Apache-2.0
# What the fault tests (fault_*.sh) share, sourced by them: the commands they
# run, written into the array CMD, and the checks on what a run leaves
# beside its output. The scripts set CMF (the cmfilter binary), SRC (the
# source tree) and WORK (a folder of their own) with fault_setup first.
#   fault_setup CMF SRC WORK              sets those, makes WORK afresh and
#                                         writes the inputs the commands read
#   fault_command KIND OUTPUT [VARIANT]   KIND: table, moments or render;
#                                         VARIANT 1: other parameters, so a
#                                         different file
# CMFILTER_FAULT_SMALL=1 (a sanitized build, whose runs are several times
# slower): a quarter of the work each, a smaller table, driver and frame.

fail=0
fail() { echo "FAIL: $*"; fail=1; }

small=${CMFILTER_FAULT_SMALL:-0}

# The moment bake's driver is 512 x 512 values (256 x 256 small), written by oiiotool.
fault_setup() {
  CMF=$1 SRC=$2 WORK=$3
  rm -rf "$WORK" && mkdir -p "$WORK" || exit 1
  local size=512x512
  [ "$small" = 1 ] && size=256x256
  oiiotool --pattern noise:type=uniform:min=0:max=1:seed=7 "$size" 1 -d float -o "$WORK/driver.exr" ||
    { echo "cannot write the driver with oiiotool"; exit 1; }
}

fault_command() {
  local kind=$1 output=$2 variant=${3:-0}
  case "$kind" in
    table)
      local values=1024 sigmas=256
      [ "$small" = 1 ] && values=512 sigmas=128
      [ "$variant" = 1 ] && values=$((values / 2))
      CMD=("$CMF" bake-colormap "$SRC/luts/terrain.png" -o "$output" --values "$values" --sigmas "$sigmas" -q) ;;
    moments)
      local wrap=clamp
      [ "$variant" = 1 ] && wrap=periodic
      CMD=("$CMF" bake-moments "$WORK/driver.exr" -o "$output" --wrap "$wrap" -q) ;;
    render)
      local method=gaussian
      [ "$variant" = 1 ] && method=naive
      CMD=("$CMF" render "$SRC/examples/scenes/plane-fbm-terrain.json" -o "$output" --method "$method" -q)
      [ "$small" = 1 ] && CMD+=(--size 320x180) ;;
    *) echo "fault_command: unknown kind $kind"; exit 2 ;;
  esac
}

# The names of OUTPUT's temporaries in its folder (".<stem>.tmp-..."), one a line.
temporaries_of() {
  local dir base stem
  dir=$(dirname "$1"); base=$(basename "$1"); stem=${base%.*}
  ls -A "$dir" | grep -F ".$stem.tmp-" || true
}

# An extended regular expression matching the text S alone.
ere_escape() { printf '%s' "$1" | sed 's/[][\.*^$()+?{}|]/\\&/g'; }

# Fails unless every temporary of OUTPUT is named as a writer on this host
# with one of the process ids PIDS (space-separated) names it:
# .<stem>.tmp-<host>-<pid>-<16 hex><ext>.
check_temporaries_named() {
  local output=$1 pids base stem ext pattern name
  pids=$(echo $2 | tr ' ' '|')
  base=$(basename "$output"); stem=${base%.*}; ext=${base##*.}
  pattern="^\.$(ere_escape "$stem")\.tmp-$(ere_escape "$(hostname)")-($pids)-[0-9a-f]{16}\.$(ere_escape "$ext")\$"
  while IFS= read -r name; do
    [ -z "$name" ] && continue
    [[ "$name" =~ $pattern ]] || fail "temporary '$name' beside $output does not match $pattern"
  done <<<"$(temporaries_of "$output")"
}

check_no_temporaries() {
  local left
  left=$(temporaries_of "$1")
  [ -z "$left" ] || fail "temporaries of $1 left: $left"
}

# Whether files A and B are the same bytes but for the date the image
# library writes into each header (OpenEXR's capDate, "YYYY:MM:DD HH:MM:SS": the
# same length): every byte that differs lies within 48 bytes after a
# "capDate" of A.
same_but_date() {
  [ -f "$1" ] && [ -f "$2" ] && [ "$(stat -c %s "$1")" = "$(stat -c %s "$2")" ] || return 1
  cmp -s "$1" "$2" && return 0
  local dates
  dates=$(grep -abo capDate "$1" | cut -d: -f1 | tr '\n' ' ')
  [ -n "$dates" ] || return 1
  cmp -l "$1" "$2" | awk -v dates="$dates" '
    BEGIN { n = split(dates, at, " ") }
    { inside = 0; for (i = 1; i <= n; ++i) if ($1 - 1 >= at[i] && $1 - 1 < at[i] + 48) inside = 1
      if (!inside) bad = 1 }
    END { exit bad }'
}

# Fails unless FILE is an image oiiotool reads whole (every pixel decoded).
check_readable() {
  oiiotool --info "$1" >/dev/null 2>&1 || fail "oiiotool --info cannot read $1"
  oiiotool "$1" --printstats >/dev/null 2>&1 || fail "oiiotool cannot read the pixels of $1"
}

# Runs CMD, its stdout and stderr to $WORK/last.out and $WORK/last.err; sets rc.
run_cmd() {
  "${CMD[@]}" >"$WORK/last.out" 2>"$WORK/last.err"
  rc=$?
}

# The number of cmfilter's own error lines in FILE ("cmfilter <command>:
# error: ..."; libpng prints lines of its own on a broken PNG).
error_lines() { grep -cE '^cmfilter [a-z-]+: error: ' "$1"; }

# Fails unless the last run failed (non-zero exit) with one error naming
# NAME (the output or input file), left no OUTPUT and no temporary of it.
check_failed_cleanly() {
  local output=$1 name=$2 what=$3
  echo "$what: exit $rc: $(cat "$WORK/last.err")"
  [ "$rc" != 0 ] || fail "$what: exit 0, expected a failure"
  [ "$(error_lines "$WORK/last.err")" = 1 ] || fail "$what: expected exactly one error from cmfilter on stderr"
  grep -qF -- "'$name'" "$WORK/last.err" || fail "$what: the message does not name '$name'"
  [ ! -e "$output" ] || fail "$what: $output exists"
  check_no_temporaries "$output"
}
