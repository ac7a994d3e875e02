"""Running one case of a study in a fresh YADE process, so that each is timed and measured without the state (memory,
caches, OpenMP pools) of the others: the parent calls :func:`runChild`, which starts the same script with
``--child <json>``; the child computes its case and hands the result back with :func:`reportChild`."""
import json
import os
import subprocess
import sys

MARKER = 'RDEM-CHILD-RESULT '


def yadeCommand():
	"""The command that starts the YADE this process runs in: the same interpreter and YADE main script (the environment,
	YADE_PREFIX and PYTHONPATH among it, is inherited), whether YADE is installed or run through a launcher."""
	from yade import config
	return [sys.executable, os.path.join(config.prefix, 'bin', 'yade' + config.suffix)]


def runChild(spec, threads=1):
	"""Run the current script (sys.argv[0]) with ``--child json(spec)`` in a fresh YADE with ``threads`` OpenMP threads
	and return the dict it reported; RuntimeError with the end of its output if it reported nothing."""
	env = dict(os.environ, OMP_NUM_THREADS=str(threads))
	cmd = yadeCommand() + ['-j%d' % threads, '-n', '-x', sys.argv[0], '--child', json.dumps(spec)]
	proc = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
	for line in proc.stdout.splitlines():
		if line.startswith(MARKER):
			return json.loads(line[len(MARKER):])
	raise RuntimeError('case %s failed:\n%s' % (spec, proc.stdout[-3000:]))


def reportChild(result):
	"""In the child: hand ``result`` (a JSON-serialisable dict) back to :func:`runChild`."""
	print(MARKER + json.dumps(result), flush=True)
