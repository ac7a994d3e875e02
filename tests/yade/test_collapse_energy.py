"""Energy through a collapse (issue #17): a structure overturned by a one-sine ground pulse (prescribed base motion,
rdem.earthquake.shaker) falls, lands and comes to rest without the model creating energy. The total energy E of
harness.EnergyBalance (leapfrog-paired kinetic energy plus every O.energy term: gravity's potential, springs, dashpots,
friction, the ground's work) never rises above its start by more than 1e-3 of the input, the energy that flows through
the motion: the work of the ground plus the potential energy the fall releases; the run ends at rest. E is evaluated
at every 50th step (its paired kinetic energy needs Python at that step); contacts of E = 1 GPa keep the test short.

* Housner's block (b = 0.1 m, h = 0.5 m, 100 kg) under 3 g tan α, period 0.5 s: overturns and lands flat on its long
  face after a fall of 392 J (centroid from 0.5 m to 0.1 m). Measured at the automatic step (48.7 µs, 0.33 of the
  undamped limit): rise 0.036 J = 8.7e-5 of the 410 J input, kinetic energy at 2.5 s 1e-25 J. The block overturns at
  1.69–1.70 s at every step from 4 µs to 48.7 µs and is at rest by 2.5 s at each, but at 2.0 s it may still be landing
  (2.3 J left at 48.7 µs), hence 2.5 s. (EnergyBalance leaves the moving base's own kinetic energy out while groundWork books
  it, so E dips while the base moves and comes back when it stops: its ``growth`` above an earlier low is that dip,
  not energy made.)
* A dry-stacked wall (rdem.earthquake.DryWall, 0.5 × 0.22 m: 4 courses, 10 blocks, contacts E = 0.1 GPa) on a base
  that reaches 0.5 m beyond it, one-sine pulse 3 g t/H (its overturning threshold g t/H, Housner's g tan α of the whole
  wall), 0.5 s, towards −y first so that it falls towards +y onto the base: the courses topple, tumble and come to rest
  on the base. Measured: no rise above the start, 47.0 J of input; after the pulse, E rises above an earlier
  value by 1.6e-13 J at most (3.5e-15; the block: 2.4e-4); kinetic energy 1.4e-26 J at 2 s. The fall is chaotic: a
  change in the last bits of the time step (RdemTimeStepper sums its stiffness in body-id order since issue #25, so that
  a reloaded run continues bit for bit) gives another path, which came to rest after 1.5 s (0.006 J of kinetic energy
  left then; 52.4 J of input and at rest at 1.5 s before), hence 2 s. On a base that ended 5 cm beyond the wall the
  blocks fell off its edge and E rose by 1.2 J of 54 J (doc/earthquake.md).

The 0.37 % rise of the block's landing once reported (doc/earthquake.md) was O.energy.total(), whose kinetic energy
½mv² at the mid-step velocity does not pair with the positions' energies; with the paired kinetic energy the landing
rises by 1.1e-5 of the input."""
import math
import unittest
import harness
from yade import O
from yade import rdem
from yade.rdem import ground_motion as gm
from yade.rdem.earthquake import DryWall
from yade.rdem.scenes import RockingBlock


def runToRest(balance, pulseEnd, duration, every, chunk=2000):
	"""Run with the energy balance ``balance`` until ``duration`` [s], and with a second one from ``pulseEnd`` [s], when
	the base has stopped: from then on nothing brings energy in and E may only fall (its ``growth`` is energy made by
	the model). Returns (the second balance, the kinetic energy at the end [J])."""
	while O.time < pulseEnd:
		balance.run(chunk, every=every)
	after = harness.EnergyBalance()
	while O.time < duration:
		after.run(chunk, every=every)
	balance.energies += after.energies
	return after, O.energy['kinetic']


def inputOf(potential0):
	"""Energy that flowed through the motion: the ground's largest work so far plus the potential energy released [J]."""
	e = dict(O.energy.items())
	return -e.get('groundWork', 0.0) + max(0.0, potential0 - e.get('gravWork', 0.0))


class CollapseEnergy(unittest.TestCase):

	def check(self, balance, after, inflow, kinetic, name):
		rise = max(balance.energies) - balance.energies[0]
		print('%s: input %.4g J, largest rise above the start %.3g J (%.2e of the input), growth above an earlier value after the pulse %.3g J (%.2e), kinetic energy at the end %.3g J'
		      % (name, inflow, rise, rise / inflow, after.growth, after.growth / inflow, kinetic))
		self.assertLess(rise, 1e-3 * inflow)
		self.assertLess(after.growth, 1e-3 * inflow)
		self.assertLess(kinetic, 1e-6 * inflow)  # at rest

	def testBlockOverturnsAndLands(self):
		harness.freshScene()
		rock = RockingBlock(b=0.1, h=0.5, young=1e9)  # soft contacts: a 5.5 times longer step
		rdem.earthquake.shaker(gm.GroundMotion(x=gm.sinePulse(3 * rock.upliftAcceleration(), 0.5, dt=1e-3, before=0.05)), ids=[rock.base])
		O.trackEnergy = True
		O.step()
		potential0 = O.energy['gravWork']
		balance = harness.EnergyBalance()
		after, kinetic = runToRest(balance, 0.55, 2.5, every=50)
		self.assertGreater(abs(rock.angle()), math.pi / 2 - 0.01)  # lying on its long face
		inflow = inputOf(potential0)
		self.assertGreater(inflow, 392)  # the fall alone: 100 kg x 9.81 x 0.4 m
		self.check(balance, after, inflow, kinetic, 'block')

	def testDryWallOverturnsAndComesToRest(self):
		harness.freshScene()
		wall = DryWall(length=0.5, height=0.22, young=1e8, baseMargin=0.5)
		self.assertEqual(len(wall.ids), 10)
		H, t = wall.layout.height, wall.layout.thickness
		rdem.earthquake.shaker(gm.GroundMotion(y=gm.sinePulse(-3 * 9.81 * t / H, 0.5, dt=1e-3, before=0.05)), ids=[wall.base])
		O.trackEnergy = True
		O.step()
		potential0 = O.energy['gravWork']
		balance = harness.EnergyBalance()
		after, kinetic = runToRest(balance, 0.55, 2.0, every=500, chunk=5000)
		top = max(O.bodies[i].state.pos[2] for i in wall.ids)
		self.assertLess(top, 0.5 * H)  # no block is left standing on another's top: the wall lies on the base
		self.assertGreater(min(O.bodies[i].state.pos[2] for i in wall.ids), 0)  # none fell off the base
		inflow = inputOf(potential0)
		self.check(balance, after, inflow, kinetic, 'dry wall')


if __name__ == '__main__':
	harness.run(CollapseEnergy)
