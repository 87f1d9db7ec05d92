#!/bin/sh
# Prints a case file with each `include FILE` line replaced by FILE's text (FILE relative to
# the case file's folder, as `chipflex run` reads it), so that a script can edit any of the
# case's keys with sed, and the result runs from any folder.
#   scripts/flatten_case.sh CASE.prm > FLAT.prm
[ $# -eq 1 ] || { echo "usage: flatten_case.sh CASE.prm" >&2; exit 2; }
folder=$(dirname "$1")
awk -v folder="$folder" '
  /^[ \t]*include[ \t]/ {
    file = $2; if (file !~ /^\//) file = folder "/" file
    while ((status = (getline line < file)) > 0) print line
    if (status < 0) { print "flatten_case.sh: " FILENAME ": cannot read " file > "/dev/stderr"; exit 1 }
    close(file); next
  }
  { print }' "$1"
