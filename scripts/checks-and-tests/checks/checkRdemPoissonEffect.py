# 2026 © yade-rdem authors
# The refined DEM with the Poisson effect (springs between rigid blocks, virtual 8-node hexahedra on their centroids;
# consistent formulation, doc/sphinx/rdemTheory.rst §5.2): a 4×4×4 cube of blocks compressed between platens that slide
# freely sideways shows the Poisson effect of its material, lateral strain = −ν × axial strain, which rigid blocks with
# springs alone cannot show (their apparent ν is 0).

from yade import rdem
from yade.rdem.scenes import CompressionTest

nu = 0.2
test = CompressionTest(blocksPerEdge=4, poisson=nu, formulation='consistent', tensileStrength=float('inf'), rate=0.01, dt=1e-7)
O.dt = 0.8 * rdem.timeStepper().estimate()
rdem.newtonIntegrator().damping = 0.4  # non-viscous damping: the static state is the same, reached in fewer steps

O.run(1000, True)  # the top platen moves down 0.01 m/s (axial strain about 1e-4 at the end)
for i in test.top:
	O.bodies[i].state.vel = Vector3(0, 0, 0)
O.run(3000, True)  # settle at the reached shortening

nuApparent = test.apparentPoisson()
print('apparent Poisson ratio %.6f (material: %g)' % (nuApparent, nu))
# Exact at equilibrium for a uniform field (doc/sphinx/rdemTheory.rst §5.2); 3000 damped steps leave it within 1e-4 of rest here.
if abs(nuApparent - nu) > 1e-3:
	raise YadeCheckError('apparent Poisson ratio %g of a 4x4x4 cube of nu = %g: differs by more than 1e-3' % (nuApparent, nu))
