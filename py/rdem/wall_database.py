"""In-plane shear tests of masonry walls from a table in the columns of the open database of modern masonry wall tests
([EESDWallsDB]_), and the one rule set that turns a row into a model: what the table gives is used as given, what it
does not give (moduli, Poisson's ratio, tensile strengths, fracture energies, friction where missing, how a hollow
unit is represented, the joints' thickness, the bond) comes from :data:`RULES`, the same for every wall, each value with
its source. No value depends on which wall it is for.

Pure Python (standard library only, no YADE): tested in tests/python/test_wall_database.py. scripts/shear_wall.py builds
and runs a model made by :func:`model` (``--wall NAME``), scripts/wall_database.py runs the whole table.

Typical use::

    from rdem import wall_database as db
    rows = db.readTable()                      # data/walls/walls.csv: {name: row}
    m = db.model(rows['MI1'])                  # geometry, materials, test, measured values, sources
    check = db.staticsCheck(rows['MI1'])       # measured peak against the rocking bound of a constant axial load

Units: SI throughout (m, Pa, kg/m³, N, J/m²); the table's mm, MPa and kN are converted by :func:`model`. Stresses are
quoted compression positive for $\\sigma_0$ (as engineers quote it) and tension positive for strengths.
"""
import csv
import math
import os

#: The validation set shipped with the project (data/walls/README.md gives its source).
TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'data', 'walls', 'walls.csv')

#: The rule set: name -> (value, source). SI units. The user guide's validation page ("Fifteen walls") lists the same.
RULES = {
        'jointThickness': ({'GP': 0.010, 'TL': 0.002}, 'EN1996-1-1 8.1.5: general-purpose mortar joints 6-15 mm, thin-layer joints 0.5-3 mm; '
                           'the nominal 10 and 2 mm make every length and height of the table a whole number of modules (unit + joint) '
                           'within 3 %'),
        'poisson': (0.25, 'EN1996-1-1 3.7.3: G = 0.4 E, i.e. nu = 0.25 (units and mortar)'),
        'youngOverStrength': (1000.0 / 1.2, 'where the table gives no E_m: EN1996-1-1 3.7.2, E = K_E f_k with K_E = 1000, and f_k = f_m/1.2 '
                              '(EN1052-1); units and mortar both get E_m, so the model wall has the masonry modulus'),
        'solidDensity': (1800.0, 'assumed: masonry of solid units; a hollow unit has (1 - void ratio) of it (the equivalent solid)'),
        'tensileOverCohesion': (1 / 1.4, 'joints and units: c = 1.4 f_t (LourencoRots1997: interface f_t 0.25, c 0.35 MPa)'),
        'unitTensileRatio': (0.065, 'unit tensile strength 0.065 f_b, the middle of 0.03-0.10 (Schubert1988 via Lourenco1996; not verified: '
                             'neither text was available to the project); for hollow units on the gross section, as f_b'),
        'friction': (0.75, 'where the table gives no mu: tan phi of the interfaces of LourencoRots1997'),
        'jointFractureEnergy': ((18.0, 125.0), 'G_f^I, G_f^II of the interfaces of LourencoRots1997 [J/m2]'),
        'unitFractureEnergy': ((80.0, 800.0), 'G_f^I of the units of LourencoRots1997 [J/m2]; G_f^II = 10 G_f^I, assumed'),
        'capFractureEnergy': (5000.0, 'G_fc of the compression cap, LourencoRots1997 [J/m2]; cap strength f_m (joints) and f_b (units), '
                              'the table\'s strengths'),
        'crackBand': (True, 'BazantOh1983: where a softening spring would snap back (its tributary length l_A + l_B longer than 2 M G/f^2, '
                      'twice Hillerborg\'s length, as for a finite element wider than the crack band), its fracture energy is kept and its strength '
                      'lowered to the equivalent strength of a vertical drop, f = sqrt(2 k G) (k = M/(l_A + l_B) the spring\'s stiffness per area; '
                      'Ip2_RdemMat_RdemMat_RdemPhys.crackBand, 1 % short of vertical); applied per bond to f_t, c and the cap (1 - r) f_c; every other '
                      'bond is unchanged (in the validation set: the springs inside the hollow clay units of PUP1-PUP6, whose f_b = 35 MPa is paired '
                      'with E_m = 3.55 GPa)'),
        'capResidual': (0.2, 'residual fraction of the cap strength after crushing: the default of RdemJoint, assumed'),
        'headJoints': ('bonded only if thin-layer filled (TF)', 'MannMuller1982: general-purpose mortar head joints are not compressed while they '
                       'harden and shrink away from the units, so they carry no bond (validated on MI1: the user guide, validation); unfilled (U) '
                       'head joints have none; both keep compression and friction'),
        'bond': ('running bond (one wythe) or English bond (one and a half bricks)', 'assumed, the table gives no bond: one wythe when the '
                 'wall is about one unit thick (the unit width is taken as the wall thickness), English bond, the usual bond of a '
                 'one-and-a-half-brick wall, when t = l + joint + w; the overlap of running bond is half a unit. The length is the one '
                 'nearest the tested length that the bond lays (rdem.wall_layout): running bond of whole and half units, English bond of whole '
                 'stretchers or whole stretchers and a three-quarter bat, as a mason closes a course'),
        'blocksPerUnit': ('2 along the unit, 1 through, round(2 h/l) >= 1 up', 'the user guide, accuracy against cost: a unit must be able to split '
                          '(1 block per brick: +23 % on MI1), 2 against 4 blocks per brick -0.6 %; blocks about as tall as long'),
        'beams': (dict(height=0.2, young=30e9, poisson=0.2, density=2400.0), 'assumed: reinforced concrete beams (EN1992-1-1 Table 3.1, C25/30: '
                  'E_cm = 31 GPa), rigid against the wall'),
        'loading': ('monotonic push of the top beam to the positive side', 'the envelope of the cyclic test; compared with the mean of the '
                    'measured positive and negative peaks'),
        'quasiStatic': (dict(rate=0.04, damping=0.2, inertiaScaling=True, densityScaling=1.0, rampTravel=1e-3, compressTime=0.02, drift=0.006, pastPeak=2.0, maxDrift=0.02,
                             stopDrop=0.2, smoothDrift=2e-4),
                        'the user guide, validation, "Quasi-static loading in fewer steps": the top beam at rate [m/s], its velocity ramped up over rampTravel [m] '
                        "of travel; Cundall's non-viscous damping; the blocks' rotational inertia scaled (rdem.quasi_static) or not; partial density "
                        'scaling of the push by the factor densityScaling on the step (rdem.walltest.scaleDensity; 1: none); sigma0 ramped over '
                        'compressTime [s] and held until the wall is at rest; the push ends once the load averaged over smoothDrift [-] of drift has '
                        'dropped by stopDrop of its peak, or once past drift [-] and pastPeak times the drift of that peak, or at maxDrift [-] (MI1 was '
                        'validated to 0.6 % drift with a 20 % drop)'),
        'shearSpan': ('H0/H = 0.5: top beam kept horizontal; otherwise it is a rigid lever pinned at H0 above the base, which makes the moment '
                      'V (H0 - H) at the masonry top at every step (rdem.walltest.applyLever)',
                      'the test set-ups of the table (H0/H, EESDWallsDB field #27); H0 = (H0/H) x the model height'),
}

#: The failure modes of the table and the class each is compared as (S shear, F flexure, H hybrid).
MODE_CLASS = {'S': 'S', 'F': 'F', 'H-FS': 'H', 'H-SF': 'H', 'H-FG': 'H', 'H-FSL': 'H', 'H-SSL': 'H'}

GRAVITY = 9.81  # [m/s2]


def rule(name):
	"""The value of the rule ``name`` of :data:`RULES`."""
	return RULES[name][0]


def _number(text):
	"""A table cell as a float, or None for an empty cell or NaN."""
	text = text.strip()
	if not text:
		return None
	try:
		v = float(text)
	except ValueError:
		return text
	return None if math.isnan(v) else v


def readTable(path=None):
	"""The rows of a table in the database's columns (default :data:`TABLE`), as ``{specimen name: row}`` in file
	order, each row a dict of the columns, numbers as floats and empty or NaN cells as None. ValueError naming the file
	if it lacks a column that :func:`model` needs."""
	path = path or TABLE
	with open(path, newline='') as f:
		rows = list(csv.DictReader(f))
	needed = ('Specimen name', 'Unit type', 'N courses', 'H [m]', 'L [m]', 't [m]', 'Bed Joints', 'Head Joints', 'Void Ratio [%]', 'lb [mm]', 'wb [mm]',
	          'hb [mm]', 'fb_perp [MPa]', 'fm_c [MPa]', 'Em [MPa]', 'fv0 [MPa]', 'mu [-]', 'H0/H [-]', 'sigma0 [MPa]', 'Failure mode', 'Vmax+ [kN]', 'Vmax- [kN]',
	          'dVmax+ [%]', 'dVmax- [%]')
	missing = [c for c in needed if rows and c not in rows[0]]
	if missing:
		raise ValueError('%s: columns missing: %s' % (path, ', '.join(missing)))
	out = {}
	for r in rows:
		row = {k: (_number(v) if k not in ('Specimen name', 'Reference', 'Unit type', 'Bed Joints', 'Head Joints', 'Failure mode') else v.strip())
		       for k, v in r.items()}
		if row['Void Ratio [%]'] == 'solid':
			row['Void Ratio [%]'] = 0.0
		out[row['Specimen name']] = row
	return out


def _nearestModules(target, module, joint, smallest, allowed=lambda n: True):
	"""The number n >= ``smallest`` of modules, with ``allowed(n)``, whose n*module - joint is nearest to ``target``
	(ties: the smaller)."""
	x = (target + joint) / module
	candidates = [n for n in range(max(smallest, int(math.floor(x)) - 4), max(smallest, int(math.ceil(x)) + 4) + 1) if allowed(n)]
	return min(candidates, key=lambda n: (abs(n - x), n))


def geometry(row):
	"""The model wall of a row: its bond, unit and joint sizes and its length, height and thickness [m] by the rules
	``jointThickness``, ``bond`` and ``blocksPerUnit``, with the deviations from the tested sizes (model/tested - 1).
	ValueError naming the column if the table's sizes fit no bond."""
	l, w, h = (row[c] * 1e-3 for c in ('lb [mm]', 'wb [mm]', 'hb [mm]'))
	L, H, t = row['L [m]'], row['H [m]'], row['t [m]']
	courses = int(row['N courses'])
	joints = rule('jointThickness')
	if row['Bed Joints'] not in joints:
		raise ValueError('Bed Joints = %r: must be one of %s' % (row['Bed Joints'], ', '.join(sorted(joints))))
	tj = joints[row['Bed Joints']]
	if abs(t - (l + tj + w)) <= 0.02 * t:
		# one and a half bricks: English bond (the header is as deep as two stretchers and a joint) of whole
		# stretchers, or whole stretchers and a three-quarter bat (rdem.wall_layout): q quarter modules, q mod 4 in {0, 3}
		bond, width = 'english', w
		q = _nearestModules(L, (l + tj) / 4, tj, 8, lambda q: q % 4 in (0, 3))
		length, thickness = q * (l + tj) / 4 - tj, l + tj + w
	elif abs(t - w) <= 0.05 * t:
		# one wythe: running bond of whole units and half units, the unit as wide as the wall
		bond, width = 'running', t
		n = _nearestModules(L, (l + tj) / 2, tj, 2)
		length, thickness = n * (l + tj) / 2 - tj, t
	else:
		raise ValueError('t [m] = %g: fits neither one wythe of units %g m wide nor one and a half bricks (%g m)' % (t, w, l + tj + w))
	height = courses * (h + tj) - tj
	along = 2
	up = max(1, int(round(2 * h / l)))
	return dict(bond=bond, brick=(l, width, h), joint=tj, length=length, height=height, thickness=thickness, courses=courses,
	            blocksPerBrick=(along, 1, up), beam=rule('beams')['height'], tested=dict(length=L, height=H, thickness=t),
	            deviation=dict(length=length / L - 1, height=height / H - 1, thickness=thickness / t - 1))


def materials(row):
	"""The materials of a row by the rule set: ``{'brick': ..., 'joint': ..., 'beam': ...}`` with the keys of
	scripts/shear_wall.py's materials (SI units), and ``'sources'``: {quantity: where its value comes from}."""
	fb, fm = row['fb_perp [MPa]'] * 1e6, row['fm_c [MPa]'] * 1e6
	sources = {}
	if row['Em [MPa]']:
		E = row['Em [MPa]'] * 1e6
		sources['E'] = 'E_m of the table (units and mortar)'
	else:
		E = rule('youngOverStrength') * fm
		sources['E'] = RULES['youngOverStrength'][1]
	void = row['Void Ratio [%]'] or 0.0
	density = rule('solidDensity') * (1 - void)
	sources['density'] = RULES['solidDensity'][1]
	nu = rule('poisson')
	ratio = rule('tensileOverCohesion')
	c = row['fv0 [MPa]'] * 1e6
	sources['joint cohesion'] = 'f_v0 of the table'
	if row['mu [-]']:
		mu = row['mu [-]']
		sources['friction'] = 'mu of the table'
	else:
		mu = rule('friction')
		sources['friction'] = RULES['friction'][1]
	fbt = rule('unitTensileRatio') * fb
	sources['unit tensile strength'] = RULES['unitTensileRatio'][1]
	GjI, GjII = rule('jointFractureEnergy')
	GuI, GuII = rule('unitFractureEnergy')
	head = 'bonded' if row['Head Joints'] == 'TF' else 'unbonded'
	sources['head joints'] = RULES['headJoints'][1]
	brick = dict(young=E, poisson=nu, density=density, tensileStrength=fbt, cohesion=fbt / ratio, mu=mu, GfI=GuI, GfII=GuII, fc=fb)
	joint = dict(young=E, poisson=nu, tensileStrength=c * ratio, cohesion=c, mu=mu, GfI=GjI, GfII=GjII, fc=fm, Gfc=rule('capFractureEnergy'),
	             residual=rule('capResidual'), headJoints=head)
	beams = rule('beams')
	beam = dict(young=beams['young'], poisson=beams['poisson'], density=beams['density'])
	return dict(brick=brick, joint=joint, beam=beam, sources=sources)


def measured(row):
	"""The measured values of a row: peaks (+, -) [N], their mean, drifts at them [-], failure mode and its class."""
	peaks = (row['Vmax+ [kN]'] * 1e3, abs(row['Vmax- [kN]']) * 1e3)
	drifts = (row['dVmax+ [%]'] * 1e-2, abs(row['dVmax- [%]']) * 1e-2)
	mode = row['Failure mode']
	return dict(peak=peaks, mean=sum(peaks) / 2, driftAtPeak=drifts, failure=mode, failureClass=MODE_CLASS.get(mode, mode))


def model(row):
	"""Everything a run needs for one row: ``name``, ``geometry`` (:func:`geometry`), ``materials``
	(:func:`materials`), ``test`` (sigma0 [Pa], shearSpan H0/H, boundary of rdem.walltest.ShearWallTest), ``measured``
	(:func:`measured`) and ``statics`` (:func:`staticsCheck`)."""
	span = row['H0/H [-]']
	if not (span and span > 0):
		raise ValueError('H0/H [-] = %r: must be > 0' % (span, ))
	test = dict(sigma0=row['sigma0 [MPa]'] * 1e6, shearSpan=span, boundary='fixed' if span == 0.5 else 'cantilever')
	return dict(name=row['Specimen name'], reference=row.get('Reference'), geometry=geometry(row), materials=materials(row), test=test,
	            measured=measured(row), statics=staticsCheck(row))


def sectionMoment(P, length, thickness=None, compressiveStrength=math.inf):
	"""The largest moment [N m] about its centre line that a bed-joint section of length $L$ and thickness $t$ [m]
	carries under an axial compression ``P`` [N] when it takes no tension and crushes at ``compressiveStrength``
	$f_m$ [Pa] (rigid-perfectly-plastic in compression: [Heyman1966]_'s no-tension material with a finite strength):
	the compressed zone is a stress block $f_m$ deep $a = P/(f_m t)$ at the compressed edge, so
	$M = P (L - a)/2 = (P L/2)(1 - P/(f_m L t))$; $P L/2$ for $f_m = \infty$ (the resultant at the corner).
	ValueError if $P > f_m L t$ (the section crushes under $P$ alone)."""
	if math.isinf(compressiveStrength):
		return P * length / 2
	if not (thickness and thickness > 0 and compressiveStrength > 0):
		raise ValueError('thickness = %r, compressiveStrength = %r: both must be > 0 [m, Pa] for a finite strength' % (thickness, compressiveStrength))
	squash = compressiveStrength * length * thickness
	if P > squash:
		raise ValueError('P = %r N exceeds the squash load f_m L t = %r N: the section crushes under its axial force alone' % (P, squash))
	return P * length / 2 * (1 - P / squash)


def rockingBound(N, W, length, height, shearSpan, thickness=None, compressiveStrength=math.inf):
	"""The largest shear $V$ [N] a wall of rigid blocks can carry under a constant axial force ``N`` [N] at its top and
	its own weight ``W`` [N] (no tension; the resultant inside the section), length $L$, height $H$ [m] and shear span
	ratio $H_0/H$, from the moments $M(P)$ its bed-joint sections carry (:func:`sectionMoment`: $P L/2$ with unlimited
	compression; with ``compressiveStrength`` $f_m$ [Pa] and ``thickness`` $t$ [m], the stress block that crushes
	at $f_m$):

	* $H_0/H = 0.5$, both ends fixed (the top kept horizontal, the moments at the top and the base not controlled):
	  the panel rocks about opposite corners, $V H = M(N) + M(N + W)$; with unlimited compression
	  $V \le (2N + W) L/(2H)$ (:ref:`validation <rdem-validation>`);
	* otherwise the top carries the moment $V (H_0 - H)$ as in the test: the base section $V H_0 \le M(N + W)$ and,
	  for $H_0 \ne H$, the top section $V |H - H_0| \le M(N)$.

	ValueError naming the argument if one is out of range."""
	for name, v in (('N', N), ('W', W)):
		if not (math.isfinite(v) and v >= 0):
			raise ValueError('%s = %r: must be finite and >= 0 [N]' % (name, v))
	for name, v in (('length', length), ('height', height), ('shearSpan', shearSpan)):
		if not (math.isfinite(v) and v > 0):
			raise ValueError('%s = %r: must be finite and > 0' % (name, v))

	def M(P):
		return sectionMoment(P, length, thickness, compressiveStrength)

	if shearSpan == 0.5:
		return (M(N) + M(N + W)) / height
	H0 = shearSpan * height
	bound = M(N + W) / H0
	if abs(height - H0) > 1e-12 * height:
		bound = min(bound, M(N) / abs(height - H0))
	return bound


def staticsCheck(row):
	"""The statics check of a row (:ref:`validation <rdem-validation>`): the tested geometry, $N = \sigma_0 L t$, the masonry's weight
	$W$ at the rule set's density, the :func:`rockingBound`; ``ratio`` = measured mean peak / bound, ``passes`` = ratio
	< 1 (a model of constant axial load can reach the measured peak), ``sigma0Needed`` [Pa]: the $\sigma_0$ at which
	the bound equals the measured mean. Also the bound of bed joints that crush at the table's $f_m$
	(``crushingBound`` [N], ``crushingRatio`` = measured mean / it) and that bound for the model's wall (``modelCrushingBound``
	[N]: :func:`geometry`'s length, height and thickness), which a model whose bed joints crush at $f_m$ cannot exceed
	unless its joints carry tension."""
	L, H, t = row['L [m]'], row['H [m]'], row['t [m]']
	density = rule('solidDensity') * (1 - (row['Void Ratio [%]'] or 0.0))
	sigma0, fm = row['sigma0 [MPa]'] * 1e6, row['fm_c [MPa]'] * 1e6
	N = sigma0 * L * t
	W = density * GRAVITY * L * H * t
	span = row['H0/H [-]']
	bound = rockingBound(N, W, L, H, span)
	mean = measured(row)['mean']
	perStress = (rockingBound(N + 1e6 * L * t, W, L, H, span) - bound) / 1e6  # the bound is linear in N
	crushing = rockingBound(N, W, L, H, span, t, fm)
	g = geometry(row)
	Lm, Hm, tm = g['length'], g['height'], g['thickness']
	modelCrushing = rockingBound(sigma0 * Lm * tm, density * GRAVITY * Lm * Hm * tm, Lm, Hm, span, tm, fm)
	return dict(axialForce=N, weight=W, bound=bound, measuredMean=mean, ratio=mean / bound, passes=mean < bound,
	            sigma0Needed=sigma0 + (mean - bound) / perStress, crushingBound=crushing, crushingRatio=mean / crushing,
	            modelCrushingBound=modelCrushing)


def failureClass(horizontalTensionArea, coreCourses, coreCoursesCracked, jointArea):
	"""The failure mode of a model wall, from its cracks at the end of the test (rule of :ref:`validation <rdem-validation>`):

	* *flexure* (rocking): in the bottom or the top tenth of the wall, the bed faces broken in tension add up to at least
	  half of one bed joint's area $L t$ (``horizontalTensionArea``: the larger of the two bands [m²], ``jointArea`` =
	  $L t$ [m²]): a rocking wall opens its heel joint over most of its length. (First fixed at a quarter; raised to a
	  half for every wall after CS01 and CS02, which failed in a diagonal stair-stepped crack as tested, opened 40 % of
	  a bed joint next to the top and were classed hybrid; :ref:`validation <rdem-validation>`.)
	* *shear*: broken springs in at least half of the courses of the wall's core (the middle half of its length and of
	  its height), as a diagonal crack through the core crosses each of them (``coreCourses`` courses, of which
	  ``coreCoursesCracked`` hold a broken spring there).

	Returns ``'S'`` (shear only), ``'F'`` (flexure only), ``'H'`` (both) or ``'-'`` (neither)."""
	if not (coreCourses >= 1 and 0 <= coreCoursesCracked <= coreCourses and jointArea > 0 and horizontalTensionArea >= 0):
		raise ValueError('failureClass: need coreCourses >= 1, 0 <= coreCoursesCracked <= coreCourses, jointArea > 0, horizontalTensionArea >= 0 '
		                 '(got %r, %r, %r, %r)' % (coreCourses, coreCoursesCracked, jointArea, horizontalTensionArea))
	flexure = horizontalTensionArea >= 0.5 * jointArea
	shear = 2 * coreCoursesCracked >= coreCourses
	return {(True, True): 'H', (True, False): 'S', (False, True): 'F', (False, False): '-'}[(shear, flexure)]
