// is-gl's context: OSMesa (Mesa's llvmpipe on the CPU, whatever GPU the machine has).
#include <memory>
#include <string>

#include "clothbench/collide_is/gl_context.hpp"
#include "clothbench/osmesa/osmesa_context.hpp"

namespace clothbench {
namespace {

class OsmesaGlContext final : public GlContext {
 public:
  OsmesaGlContext() : context_("is-gl") {}
  bool make_current(int /*k*/) override { return context_.make_current(); }
  void release() override { osmesa::Context::release(); }
  void* proc(const char* name) override { return osmesa::proc_address(name); }
  std::string renderer_name() const override { return "gl"; }
  std::string provider() const override { return "OSMesa"; }

 private:
  osmesa::Context context_;
};

}  // namespace

std::unique_ptr<MapRenderer> make_gl_map_renderer() {
  return make_gl_map_renderer(std::make_unique<OsmesaGlContext>());
}

}  // namespace clothbench
