"""yade-rdem: the refined distinct element method with the Poisson effect, for YADE.

Typical use inside a YADE script (``yade script.py`` with the launcher made by the build)::

    from yade import *
    from yade import rdem
    mat = O.materials.append(RdemMat(young=30e9, poisson=0.2, density=2300, tensileStrength=4.5e6))
    O.engines = rdem.engines(segmentsPerEdge=2, formulation='paper')
    ids = rdem.blockGrid((10, 10, 10), (0.02, 0.02, 0.02), material=mat)
    rdem.bond(ids)
    rdem.poissonEngine().build(ids)
    O.dt = 0.8 * rdem.timeStepper().estimate()

Modules: :mod:`rdem.build` (blocks, bonds, engine lists), :mod:`rdem.measure` (stresses, apparent moduli, cracks),
:mod:`rdem.export` (ParaView files of cracks and Poisson elements), :mod:`rdem.scenes` (the paper's compression test),
:mod:`rdem.batch` (cases of a study in fresh YADE processes), :mod:`rdem.wall_layout` (masonry wall geometry: bricks,
mortar and their touching pairs as plain boxes; pure Python: without YADE, ``import rdem`` gives only this module),
:mod:`rdem.building_layout` (buildings: walls bonded at corners and T-junctions, storeys, openings, floors; pure Python),
:mod:`rdem.building` (``rdem.masonry.building``: a building as a scene), :mod:`rdem.ground_motion` (earthquake records,
their velocity and displacement, baseline correction, synthetic pulses; numpy only; without YADE ``import rdem`` gives
it, rdem.wall_layout and rdem.building_layout).
"""
from .wall_layout import wallLayout, WallLayout
from .building_layout import buildingLayout, BuildingLayout
from . import ground_motion

try:
	import yade as _yade
except ModuleNotFoundError as e:  # plain Python: only the YADE-free modules (rdem.wall_layout)
	if e.name != 'yade':
		raise
	_yade = None

if _yade is not None:
	from .build import block, blockGrid, bond, bondPairs, engines, run, poissonEngine, newtonIntegrator, timeStepper, law, geomFunctor, contactGate, collider
	from . import masonry, earthquake
	from .measure import segmentTable, bondSnapshot, brokenSegments, breakCounts, apparentPoisson, dissipatedEnergy
	from .export import CrackExport

__all__ = ['wallLayout', 'WallLayout', 'buildingLayout', 'BuildingLayout', 'ground_motion'] + ([
        'block', 'blockGrid', 'bond', 'bondPairs', 'masonry', 'earthquake', 'engines', 'run', 'poissonEngine', 'newtonIntegrator', 'timeStepper', 'law', 'geomFunctor', 'contactGate', 'collider', 'segmentTable', 'bondSnapshot', 'brokenSegments', 'breakCounts',
        'apparentPoisson', 'dissipatedEnergy', 'CrackExport'
] if _yade is not None else [])
