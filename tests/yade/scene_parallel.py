"""Helper of test_assembly.testSerialEqualsOpenMP: a small breaking compression run; prints final positions as JSON."""
import json
from yade import O
from yade import rdem
from yade.rdem.scenes import CompressionTest

CompressionTest(blocksPerEdge=4, tensileStrength=2e6, rate=0.5, dt=2e-6)
rdem.run(60)
print('POSITIONS ' + json.dumps([list(b.state.pos) for b in O.bodies]))
