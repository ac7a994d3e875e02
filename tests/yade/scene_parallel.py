"""Helper of test_assembly.testSerialEqualsOpenMP: a small breaking compression run; prints final positions as JSON."""
import json
from yade import O
from rdem.scenes import CompressionTest

CompressionTest(blocksPerEdge=4, tensileStrength=2e6, rate=0.5, dt=2e-6)
O.run(60, True)
print('POSITIONS ' + json.dumps([list(b.state.pos) for b in O.bodies]))
