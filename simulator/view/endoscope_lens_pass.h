#pragma once
/// The optics of a rigid endoscope as one image-space render pass over the rendered scene:
/// barrel distortion of the wide-angle rod lens, depth of field around the focus distance
/// (seed 002 §4: the circle of confusion of an out-of-focus point, done as a post pass instead
/// of the paper's jittered eye positions), the round field stop of the eyepiece, and the haze of
/// blood in the distension fluid (seed 000 §6.2: "the view is clouded") and the steaming of the
/// lens (seed 001 §4.2).
///
/// The delegate pass renders colour and depth into textures; one full-screen fragment shader
/// then, for every output pixel at normalised radius r (1 = the edge of the round field),
/// samples the scene at r (1 + k r²) (the inverse of the lens's barrel mapping), blurs it over
/// a disc whose radius grows with |1/z − 1/f| (thin-lens circle of confusion, z the eye depth
/// and f the focus distance, both in m) and paints black outside the field. No read-back: the
/// scene stays in GPU textures, possibly rendered at a reduced `render_scale`.

#include <vtkDepthImageProcessingPass.h>
#include <vtkSmartPointer.h>

#include <memory>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace viscera::view {

/// Barrel distortion, depth of field and the round field stop of an endoscope's optics.
class EndoscopeLensPass : public vtkDepthImageProcessingPass {
 public:
  static EndoscopeLensPass* New();
  vtkTypeMacro(EndoscopeLensPass, vtkDepthImageProcessingPass)

      /// Radial distortion coefficient k (dimensionless, ≥ 0; 0 is a pinhole camera).
      double distortion = 0.2;
  /// Distance of sharpest focus in m (InstrumentSpec::focus_distance).
  double focus_distance = 0.015;
  /// Blur radius in pixels per dioptre (1/m) of defocus |1/z − 1/f|; 0 disables depth of field.
  double blur_per_dioptre = 0.06;
  /// Largest blur radius in pixels.
  double max_blur = 6.0;
  /// Paint the outside of the round field black.
  bool field_stop = true;
  /// Fraction of the output size at which the scene is rendered (0.25 … 1): the lens pass
  /// resamples it anyway (distortion, blur), so 0.5 costs a quarter of the rasterisation for a
  /// slightly softer image. Blur radii stay in output pixels. Below 0.5 the composite itself is
  /// drawn at twice the scene's resolution and stretched onto the view (a linear blit): a
  /// software renderer's full-size composite costs as much as the scene.
  double render_scale = 1.0;
  /// Blood clouding the distension fluid (issue 18 §5): a pixel at eye depth z (m) keeps
  /// exp(−haze_density·z) of its colour and takes the rest from haze_colour — Beer–Lambert
  /// with the blood's mean extinction along the line of sight, 1/m (0: clear fluid).
  double haze_density = 0.0;
  double haze_colour[3] = {0.42, 0.04, 0.03};
  /// Steam condensed on the lens (seed 001 §4.2: a texture in front of the camera made visible
  /// by decreasing its transparency gradually), 0 (clear) … 1: the image is blurred by up to
  /// max_blur and veiled towards a pale grey by a blotchy condensation pattern (value noise over
  /// the field, fixed to the lens), more at the rim where the lens is colder.
  double lens_fog = 0.0;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  EndoscopeLensPass(const EndoscopeLensPass&) = delete;
  void operator=(const EndoscopeLensPass&) = delete;

 protected:
  EndoscopeLensPass();
  ~EndoscopeLensPass() override;

 private:
  /// Binds (pushing the bindings) a framebuffer over a `width` × `height` colour texture.
  void bind_composite(vtkOpenGLRenderWindow* window, int width, int height);

  vtkSmartPointer<vtkOpenGLFramebufferObject> framebuffer_;
  vtkSmartPointer<vtkTextureObject> colour_;
  vtkSmartPointer<vtkTextureObject> depth_;
  /// The reduced composite (render_scale < 0.5), blitted onto the view.
  vtkSmartPointer<vtkOpenGLFramebufferObject> composite_framebuffer_;
  vtkSmartPointer<vtkTextureObject> composite_;
  std::unique_ptr<vtkOpenGLQuadHelper> quad_;
};

}  // namespace viscera::view
