#include "renders/crossing_view.h"

#include "renders/perspective_view.h"
#include "renders/side_view.h"
#include "renders/top_view.h"

namespace railjoint {

std::unique_ptr<CrossingView> CrossingView::make(const RenderSettings& settings, const RailJointMesh& rails,
                                                 const TriangleMesh& wheel, const Trajectory& trajectory) {
  switch (settings.view) {
    case RenderView::side:
      return std::make_unique<SideView>(settings, rails, wheel, trajectory);
    case RenderView::top:
      return std::make_unique<TopView>(settings, rails, wheel, trajectory);
    case RenderView::perspective:
      break;
  }
  return std::make_unique<PerspectiveView>(settings, rails, wheel, trajectory);
}

void CrossingView::render_at(double t_s, RgbImage& out) {
  ReadBackFrame read_back;
  draw_at(t_s, read_back);
  finish_frame(read_back, out);
}

void CrossingView::draw_at(double t_s, ReadBackFrame& out) {
  update_meshes(t_s);
  setup_.gl->draw(frame_at(t_s), out);
}

}  // namespace railjoint
