/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemGeom.hpp>

namespace yade {

YADE_PLUGIN((RdemGeom));

vector<Vector3r> RdemGeom::segDispPy() const
{
	if (normal.squaredNorm() == 0) return {}; // no frame yet (e.g. after O.load, before the next step's Ig2)
	vector<Vector3r> out(nSegments());
	Vector3r         r2;
	for (size_t i = 0; i < out.size(); ++i)
		segmentKinematics(i, out[i], r2);
	return out;
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
