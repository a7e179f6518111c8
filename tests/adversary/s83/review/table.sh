#!/bin/sh
# compact verdict table from verify logs: id size method verdict
grep -hE "^adv" "$@" | sed -E 's/^([^ ]+) \(([0-9]+,[0-9]+)\) ([a-z]+): ([a-z]+).*/\1 \2 \3 \4/' | sort
