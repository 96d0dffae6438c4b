#!/bin/sh
# The options of each subcommand, as a help2man include file (help2man --include): a program's
# own --help lists only its top-level options, and a subcommand's are in `PROGRAM SUB --help`.
# Usage: man_subcommands.sh PROGRAM OUT.h2m [NAME]. Writes OUT.h2m whole or fails; every page
# gets a SEE ALSO (help2man refuses an include with no section).
set -eu
program=$1
out=$2
tmp=$out.tmp
name=${3:-$(basename "$program")}
# Subcommand names: the first word of each line under "Subcommands:" (CLI11's --help layout).
subs=$("$program" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }
  on && /^[^ ]/ { on = 0 }')
{
  if [ -n "$subs" ]; then
    echo "[SUBCOMMANDS]"
    for sub in $subs; do
      echo ".SS \"$sub\""
      echo ".nf"
      # roff: a backslash is \e, and a line that starts with . or ' is text, not a request.
      # The usage line names the program as it was run (a build path): its name alone.
      "$program" "$sub" --help | sed -e "s|[^ ]*/$name\b|$name|g" -e 's/\\/\\e/g' \
        -e "s/^\\([.']\\)/\\\\\\&\\1/"
      echo ".fi"
    done
  fi
  echo "[SEE ALSO]"
  echo "The source tree's README.md and docs/: docs/configuration.md lists every key of every"
  echo "file, docs/recording-format.md the recordings every tool writes and reads."
} >"$tmp"
mv "$tmp" "$out"
