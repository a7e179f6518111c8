#!/bin/sh
# summarize.sh: every verdict other than error/undecided in logs/ (claim, size, method, verdict)
grep -h "^r81" logs/*.log | grep -v ": error\|: undecided" | sed 's/ (\([0-9.]*\)s.*//' | sort | uniq
