# Run by tools/docs.sh inside YADE with the plugin (build/bin/yade -n -x doc/sphinx/build.py SRC OUT), as YADE runs its
# own doc/sphinx/yadeSphinx.py: Sphinx then imports the live classes for the reference. Writes OUT/html and
# OUT/warnings.txt; exit status that of Sphinx.
import sys
from sphinx.cmd.build import build_main

src, out = sys.argv[1], sys.argv[2]
status = build_main(['-b', 'html', '-E', '-q', '-d', out + '/doctrees', '-w', out + '/warnings.txt', src, out + '/html'])
sys.exit(status)
