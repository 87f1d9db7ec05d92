#!/bin/sh
# Prints a Python interpreter that imports h5py, or nothing. Debian's python3-h5py lives
# beside /usr/bin/python3, which need not be the first python3 on PATH.
#   usage: python=$(sh tests/python_with_h5py.sh)
for p in python3 /usr/bin/python3; do
  if command -v "$p" > /dev/null 2>&1 && "$p" -c "import h5py" > /dev/null 2>&1; then
    echo "$p"
    exit 0
  fi
done
