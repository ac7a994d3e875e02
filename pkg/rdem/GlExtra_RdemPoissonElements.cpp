/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#ifdef YADE_OPENGL

#include <lib/opengl/OpenGLWrapper.hpp>
#include <core/Scene.hpp>
#include <pkg/rdem/GlExtra_RdemPoissonElements.hpp>
#include <pkg/rdem/RdemPoissonEngine.hpp>
#include <pkg/rdem/math/CrackDisplay.hpp>
#include <pkg/rdem/math/Hex8.hpp>

namespace yade {

YADE_PLUGIN((GlExtra_RdemPoissonElements));

void GlExtra_RdemPoissonElements::render()
{
	const RdemPoissonEngine* engine = scene ? RdemPoissonEngine::of(scene) : nullptr;
	const OpenGLRenderer*    r      = scene ? scene->renderer.get() : nullptr;
	if (!engine || !r) return;
	const vector<int>&                nodes = engine->nodes;     // fixed by build()
	const vector<Real>&               scale = engine->scalePrev; // written by the engine each step; sized once per build
	const size_t                      nEl   = nodes.size() / 8;
	const std::lock_guard<std::mutex> lock(scene->bodies->drawloopmutex);
	glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LINE_BIT);
	glDisable(GL_LIGHTING);
	glLineWidth(GLfloat(lineWidth));
	glBegin(GL_LINES)
		;
		for (size_t e = 0; e < nEl; ++e) {
			glColor3v(rdem::elementColour<Real>(scale.size() == nEl ? scale[e] : Real(1), color, releasedColor));
			for (const auto& edge : rdem::hex8Edges) {
				const size_t a = size_t(nodes[8 * e + size_t(edge[0])]), b = size_t(nodes[8 * e + size_t(edge[1])]);
				if (a >= r->bodyDisp.size() || b >= r->bodyDisp.size()) continue; // a block erased or added since the last frame
				glVertex3v(r->bodyDisp[a].pos);
				glVertex3v(r->bodyDisp[b].pos);
			}
		}
	glEnd();
	glPopAttrib();
}

} // namespace yade

#endif // YADE_OPENGL
