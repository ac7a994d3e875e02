/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemGeom.hpp>
#include <stdexcept>

namespace yade {

YADE_PLUGIN((RdemGeom));

Vector2r RdemGeom::segmentCoordinates(size_t k) const { return rdem::segmentCoordinates<Real>(k, samplesPerEdge); }

namespace {
	/// Centres of the n×n segments of a face with centre c and segment half-size vectors u, v (one body frame) [m].
	vector<Vector3r> segmentGrid(const Vector3r& c, const Vector3r& u, const Vector3r& v, int n)
	{
		vector<Vector3r> out;
		for (const auto& sp : rdem::segmentCentres<Real>(c, u.normalized(), v.normalized(), n * u.norm(), n * v.norm(), n))
			out.push_back(sp.pos);
		return out;
	}
}

vector<Vector3r> RdemGeom::segmentPoints1() const { return bonded ? segmentGrid(faceCentre1, segHalf1u, segHalf1v, samplesPerEdge) : vector<Vector3r>(); }

vector<Vector3r> RdemGeom::segmentPoints2() const { return bonded ? segmentGrid(faceCentre2, segHalf2u, segHalf2v, samplesPerEdge) : vector<Vector3r>(); }

vector<Vector3r> RdemGeom::segDispPy(const shared_ptr<State>& s1, const shared_ptr<State>& s2) const
{
	if (!s1 || !s2) throw std::invalid_argument("RdemGeom.segDisp: state1 and state2 must be the states of the pair's bodies, not None");
	const auto       k = kinematics(s1->ori.toRotationMatrix(), s2->ori.toRotationMatrix(), s2->pos - s1->pos);
	vector<Vector3r> out(nSegments());
	for (size_t i = 0; i < out.size(); ++i) {
		const Vector2r sr = segmentCoordinates(i);
		out[i]            = k.displacement(sr[0], sr[1]);
	}
	return out;
}

namespace {
	/// One value per spring of a patch, `of(springs, i)` (the Python accessors of ``patch``).
	template <class T, class Of> vector<T> perSpring(const rdem::PatchSprings<Real>& springs, Of of)
	{
		vector<T> out;
		out.reserve(springs.size);
		for (size_t i = 0; i < springs.size; ++i)
			out.push_back(of(springs, i));
		return out;
	}
}

vector<Vector3r> RdemGeom::patchPoints1() const
{
	return perSpring<Vector3r>(patchSprings(), [](const rdem::PatchSprings<Real>& s, size_t i) { return s.point1(i); });
}

vector<Vector3r> RdemGeom::patchPoints2() const
{
	return perSpring<Vector3r>(patchSprings(), [](const rdem::PatchSprings<Real>& s, size_t i) { return s.point2(i); });
}

vector<Real> RdemGeom::patchAreas() const
{
	return perSpring<Real>(patchSprings(), [](const rdem::PatchSprings<Real>& s, size_t i) { return s.area(i); });
}

void RdemGeom::clearSamples()
{
	sampleKey.clear();
	samplePoint.clear();
	sampleNormal.clear();
	sampleVel.clear();
	sampleDepth.clear();
	sampleArea.clear();
}

} // namespace yade
