/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#ifdef YADE_OPENGL

#include <lib/high-precision/Constants.hpp>
#include <lib/opengl/OpenGLWrapper.hpp>
#include <core/Scene.hpp>
#include <pkg/common/OpenGLRenderer.hpp>
#include <pkg/rdem/Gl1_RdemPhys.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/math/CrackDisplay.hpp>
#include <pkg/rdem/math/SegmentGrid.hpp>

namespace yade {

YADE_PLUGIN((Gl1_RdemPhys));

Vector3r Gl1_RdemPhys::tensionColor;
Vector3r Gl1_RdemPhys::shearColor;
Vector3r Gl1_RdemPhys::crushingColor;
Vector3r Gl1_RdemPhys::contactColor;
Real     Gl1_RdemPhys::fill;
Real     Gl1_RdemPhys::lineWidth;

namespace {
	/// Position and orientation at which the renderer shows body b (its dispScale, rotScale), else its state's.
	std::pair<Vector3r, Quaternionr> displayed(const Scene* scene, const Body& b)
	{
		const OpenGLRenderer* r = scene ? scene->renderer.get() : nullptr;
		if (r && size_t(b.getId()) < r->bodyDisp.size()) {
			const auto& d = r->bodyDisp[size_t(b.getId())];
			return { d.pos, d.ori };
		}
		return { b.state->pos, b.state->ori };
	}

	void quadVertices(const std::array<Vector3r, 4>& q)
	{
		for (const Vector3r& v : q)
			glVertex3v(v);
	}
}

void Gl1_RdemPhys::go(const shared_ptr<IPhys>& ip, const shared_ptr<Interaction>& I, const shared_ptr<Body>& b1, const shared_ptr<Body>&, bool wire)
{
	const shared_ptr<IGeom> ig(I->geom); // the interaction may lose its geometry meanwhile
	const auto*             g = dynamic_cast<const RdemGeom*>(ig.get());
	if (!g || !g->bonded || !b1) return;
	const RdemPhys& p    = static_cast<const RdemPhys&>(*ip);
	const size_t    nSeg = g->nSegments();
	// segState and segSigma are sized once, when the bond is made (Ip2_RdemMat_RdemMat_RdemPhys); segCrush with softening only.
	if (p.segState.size() != nSeg || p.segSigma.size() != nSeg) return;
	const bool   crushable = p.segCrush.size() == nSeg;
	Marks        marks(nSeg);
	vector<bool> closed(nSeg);
	bool         any = false; // most bonds are intact: nothing to draw, no GL state to change
	for (size_t k = 0; k < nSeg; ++k) {
		marks[k]  = rdem::segmentMark<Real>(p.segState[k], crushable ? p.segCrush[k] : Real(0));
		closed[k] = rdem::segmentInContact(p.segState[k], p.segSigma[k]);
		any       = any || marks[k] != rdem::SegmentMark::None;
	}
	if (!any) return;
	drawFace(scene, *b1, g->faceCentre1, g->segHalf1u, g->segHalf1v, g->samplesPerEdge, marks, closed, wire);
}

void Gl1_RdemPhys::drawFace(
        const Scene*        scene,
        const Body&         b1,
        const Vector3r&     c,
        const Vector3r&     a,
        const Vector3r&     b,
        int                 n,
        const Marks&        marks,
        const vector<bool>& closed,
        bool                wire)
{
	const auto pose = displayed(scene, b1);
	const Real f    = math::min(math::max(fill, Real(0.05)), Real(1));
	glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT);
	glPushMatrix();
	glDisable(GL_LIGHTING); // flat colours: a picture shows exactly the attribute's RGB
	glDisable(GL_CULL_FACE);
	glLineWidth(GLfloat(lineWidth));
	glTranslatev(pose.first);
	const AngleAxisr aa(pose.second);
	glRotate(aa.angle() * Mathr::RAD_TO_DEG, aa.axis()[0], aa.axis()[1], aa.axis()[2]);
	for (size_t k = 0; k < marks.size() && k < size_t(n * n); ++k) {
		if (marks[k] == rdem::SegmentMark::None) continue;
		const Vector2r sr = rdem::segmentCoordinates<Real>(k, n);
		const auto     q  = rdem::segmentQuad<Real>(c, a, b, sr[0], sr[1], f);
		glColor3v(marks[k] == rdem::SegmentMark::Tension ? tensionColor : marks[k] == rdem::SegmentMark::Shear ? shearColor : crushingColor);
		glBegin(wire ? GL_LINE_LOOP : GL_QUADS)
			;
			quadVertices(q);
		glEnd();
		if (k < closed.size() && closed[k]) {
			glColor3v(contactColor);
			glBegin(GL_LINE_LOOP)
				;
				quadVertices(q);
			glEnd();
		}
	}
	glPopMatrix();
	glPopAttrib();
}

} // namespace yade

#endif // YADE_OPENGL
