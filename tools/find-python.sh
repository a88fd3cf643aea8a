#!/usr/bin/env bash
# Prints a Python 3 that can import jinja2: the python3 on PATH if it can,
# else Debian's /usr/bin/python3 (tools/setup.sh installs python3-jinja2 for it).
python=$(command -v python3 || true)
if [ -n "$python" ] && "$python" -c "import jinja2" 2>/dev/null; then
  echo "$python"
else
  echo /usr/bin/python3
fi
