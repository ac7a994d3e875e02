"""A free-standing parapet on a roof under one-sine pulses (issue 26, must-show 3; doc/out-of-plane.md §3).

The parapet (0.12 m thick, 0.6 m tall: b = 0.06 m, h = 0.3 m, alpha = 0.197 rad, p = 4.90 rad/s) stands dry on the roof,
contacts at the vertices with critical dashpots, friction 1.0. The roof moves with the pulse a(t) = A sin(2 pi t/T),
0 <= t <= T. The reference is the rigid block's exact equation of motion with Housner's impacts (rdem.rocking, integrated
here): the smallest overturning amplitude A_min(T). For three periods (omega_p/p = 4.3, 2.6, 1.3) the model must not
overturn at 0.95 A_min and must overturn at 1.05 A_min, that is its own smallest overturning amplitude is within 5 % of
the equation's (the equation itself is checked not to overturn at 0.95 A_min and to overturn at 1.05 A_min, since the
overturning amplitudes of a one-sine pulse are not an interval)."""
import unittest
import harness
from yade import O
from rdem.out_of_plane import Parapet
from rdem.rocking import RockingBlockEquation

B, H = 0.06, 0.3
PERIODS = (0.3, 0.5, 1.0)


class ParapetUnderPulses(unittest.TestCase):

	def testSmallestOverturningAmplitude(self):
		eq = RockingBlockEquation(B, H)
		for T in PERIODS:
			a = eq.minimumOverturningAmplitude(T, step=0.02)
			pulse = lambda A: (lambda t: A * __import__('math').sin(2 * 3.141592653589793 * t / T) if t <= T else 0.0)
			self.assertFalse(eq.overturns(pulse(0.95 * a), T), 'T = %g: the equation overturns at 0.95 A_min' % T)
			self.assertTrue(eq.overturns(pulse(1.05 * a), T), 'T = %g: the equation does not overturn at 1.05 A_min' % T)
			for factor, expected in ((0.95, False), (1.05, True)):
				harness.freshScene()
				p = Parapet(b=B, h=H)
				over, largest = p.shake(factor * a, T)
				self.assertEqual(over, expected, 'T = %g s, A = %.3f m/s2 (%.2f A_min): overturned %s, largest rotation %.3f rad' % (T, factor * a, factor, over, largest))


if __name__ == '__main__':
	harness.run(ParapetUnderPulses)
