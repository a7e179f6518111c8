# ruff: noqa
# Copies the pytest folders of this review to $1 (default /tmp/x) under the names pytest collects: the test modules
# and the doctest text are kept here as *.in so that the project's own `make test` never imports or runs them (they
# replace runner.verify in the process that imports them).
set -e
D=${1:-/tmp/x}; H=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$D"; rm -rf "$D/ibt" "$D/dtxt" "$D/pkc" "$D/pfs"
cp -r "$H/imported_by_test" "$D/ibt";   mv "$D/ibt/test_helpers.py.in" "$D/ibt/test_helpers.py"
cp -r "$H/doctest_txt" "$D/dtxt";       mv "$D/dtxt/test_notes.txt.in" "$D/dtxt/test_notes.txt"
cp -r "$H/pkg_continue" "$D/pkc";       mv "$D/pkc/a_pkg/test_trivial.py.in" "$D/pkc/a_pkg/test_trivial.py"; mv "$D/pkc/a_pkg/__init__.py.in" "$D/pkc/a_pkg/__init__.py"
cp -r "$H/python_files_slash" "$D/pfs"
echo "copied to $D: ibt dtxt pkc pfs"
