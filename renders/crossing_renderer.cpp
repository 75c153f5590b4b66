#include "renders/crossing_renderer.h"

#include <stdexcept>
#include <string>

#include "renders/crossing_setup.h"
#include "renders/crossing_view.h"
#include "renders/perspective_view.h"
#include "renders/side_view.h"
#include "renders/top_view.h"

namespace railjoint {

namespace {

std::unique_ptr<CrossingView> make_view(CrossingSetup& setup, const RailJointMesh& rails, const TriangleMesh& wheel) {
  switch (setup.settings.view) {
    case RenderView::side:
      return std::make_unique<SideView>(setup, rails, wheel);
    case RenderView::top:
      return std::make_unique<TopView>(setup, rails, wheel);
    case RenderView::perspective:
      break;
  }
  return std::make_unique<PerspectiveView>(setup, rails, wheel);
}

}  // namespace

CrossingRenderer::CrossingRenderer(const RenderSettings& settings, const RailJointMesh& rails,
                                   const TriangleMesh& wheel, const Trajectory& trajectory)
    : setup_(std::make_unique<CrossingSetup>(settings, rails, wheel, trajectory)),
      view_(make_view(*setup_, rails, wheel)) {}

CrossingRenderer::~CrossingRenderer() = default;

const FrameWindow& CrossingRenderer::window() const { return setup_->window; }
const std::string& CrossingRenderer::gl_version() const { return setup_->gl->gl_version(); }
const std::string& CrossingRenderer::gl_renderer() const { return setup_->gl->gl_renderer(); }
Eigen::Vector3d CrossingRenderer::focus_at(double t_s) const { return view_->focus_at(t_s); }
Camera CrossingRenderer::camera_at(double t_s) const { return view_->camera_at(t_s); }

TopView* CrossingRenderer::top() const { return dynamic_cast<TopView*>(view_.get()); }

const PerspectiveView* CrossingRenderer::perspective() const {
  return dynamic_cast<const PerspectiveView*>(view_.get());
}

void CrossingRenderer::show_contact_patch(const PressureInputs& inputs) {
  if (TopView* view = top()) view->show_contact_patch(inputs);
}

std::optional<PatchPlacement> CrossingRenderer::contact_patch_at(double t_s) const {
  const TopView* view = top();
  return view ? view->contact_patch_at(t_s) : std::nullopt;
}

void CrossingRenderer::render_frame(long long k, RgbImage& out) {
  ReadBackFrame read_back;
  draw_frame(k, read_back);
  finish_frame(read_back, out);
}

void CrossingRenderer::draw_frame(long long k, ReadBackFrame& out) {
  const FrameWindow& window = setup_->window;
  if (k < 0 || k >= window.count) {
    throw std::out_of_range("render: frame " + std::to_string(k) + " is outside 0 .. " +
                            std::to_string(window.count - 1));
  }
  draw_at(window.time_s(k), out);
}

void CrossingRenderer::render_at(double t_s, RgbImage& out) {
  ReadBackFrame read_back;
  draw_at(t_s, read_back);
  finish_frame(read_back, out);
}

void CrossingRenderer::draw_at(double t_s, ReadBackFrame& out) {
  view_->update_meshes(t_s);
  setup_->gl->draw(view_->frame_at(t_s), out);
}

}  // namespace railjoint
