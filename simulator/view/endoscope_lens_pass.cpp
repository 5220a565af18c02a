#include "simulator/view/endoscope_lens_pass.h"

#include <vtkCamera.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace viscera::view {

vtkStandardNewMacro(EndoscopeLensPass);

namespace {

// Declarations and body of the fragment shader (VTK's full-screen-quad template provides
// texCoord in [0, 1]² and gl_FragData). Depth in the texture is the window depth d ∈ [0, 1];
// the eye depth is z = 2nf / (f + n − (2d − 1)(f − n)).
const char* kDeclarations = R"(
uniform sampler2D colour;
uniform sampler2D depth;
uniform float aspect;        // width / height of the output
uniform float sceneAspect;   // width / height of the rendered scene (1: the field's square)
uniform float nearPlane;
uniform float farPlane;
uniform float distortion;    // k of r_scene = r (1 + k r^2)
uniform float focusDioptres; // 1 / focus distance, 1/m
uniform float blurPerDioptre;
uniform float maxBlur;       // px
uniform float texelsPerPixel; // scene texels per output pixel (the render scale)
uniform int fieldStop;
uniform float hazeDensity;   // 1/m
uniform vec3 hazeColour;
uniform float lensFog;       // 0 (clear) ... 1 (steamed up)
float fogHash(vec2 c) { return fract(sin(dot(c, vec2(127.1, 311.7))) * 43758.5453); }
float fogNoise(vec2 x) {
  vec2 i = floor(x), f = fract(x);
  vec2 s = f * f * (3.0 - 2.0 * f);
  return mix(mix(fogHash(i), fogHash(i + vec2(1.0, 0.0)), s.x),
             mix(fogHash(i + vec2(0.0, 1.0)), fogHash(i + vec2(1.0, 1.0)), s.x), s.y);
}
float eyeDepth(vec2 uv) {
  float d = texture(depth, uv).r;
  return 2.0 * nearPlane * farPlane /
         (farPlane + nearPlane - (2.0 * d - 1.0) * (farPlane - nearPlane));
}
)";

const char* kBody = R"(
  // Normalised field coordinates: the round field touches the top and bottom of the image.
  vec2 p = (texCoord - 0.5) * 2.0 * vec2(aspect, 1.0);
  float r2 = dot(p, p);
  if (fieldStop == 1 && r2 > 1.0) { gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0); return; }
  vec2 q = p * (1.0 + distortion * r2);
  // The field edge (r = 1, q = 1 + k) meets the top of the rendered image.
  vec2 uv = q / ((1.0 + distortion) * 2.0 * vec2(sceneAspect, 1.0)) + 0.5;
  if (uv.x < 0.0 || uv.x > 1.0 || uv.y < 0.0 || uv.y > 1.0) {
    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0); return;
  }
  float z = eyeDepth(uv);
  float radius = min(maxBlur, blurPerDioptre * abs(1.0 / z - focusDioptres));
  // Condensation on the lens: blotches (two octaves of value noise), denser towards the rim.
  // A clear lens skips the noise (eight sines a pixel, a software renderer's largest cost here).
  float steam = 0.0;
  if (lensFog > 0.0) {
    float blotch = 0.6 * fogNoise(p * 5.0) + 0.4 * fogNoise(p * 13.0 + 7.0);
    steam = clamp(lensFog * (0.55 + 0.45 * blotch + 0.3 * r2), 0.0, 1.0);
  }
  radius = max(radius, steam * maxBlur);
  // The circle of confusion as one trilinear fetch from the scene's mipmap chain: level L
  // averages 2^L texels, so L = log2(diameter in scene texels) blurs over about the disc.
  float lod = log2(max(1.0, 2.0 * radius * texelsPerPixel));
  vec3 rgb = textureLod(colour, uv, lod).rgb;
  // Blood in the fluid between the lens and the surface (Beer–Lambert over the eye depth).
  rgb = mix(hazeColour, rgb, exp(-hazeDensity * z));
  rgb = mix(rgb, vec3(0.78, 0.80, 0.80), 0.6 * steam);
  // The rod lens loses light towards the rim of the field (cos^4 law, gently).
  float fall = 1.0 - 0.35 * r2 * r2;
  gl_FragData[0] = vec4(rgb * fall, 1.0);
)";

}  // namespace

EndoscopeLensPass::EndoscopeLensPass() = default;
EndoscopeLensPass::~EndoscopeLensPass() = default;

void EndoscopeLensPass::Render(const vtkRenderState* state) {
  NumberOfRenderedProps = 0;
  if (DelegatePass == nullptr) return;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* gl = window->GetState();

  int size[2];
  int origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  const int width = size[0], height = size[1];
  // The scene's resolution: the output's, scaled down by render_scale.
  const double scale = std::clamp(render_scale, 0.25, 1.0);
  // With the field stop only the centred square the round field spans is ever sampled (the
  // field's edge maps to the top and bottom of the scene), so only that square is rendered.
  const bool square = field_stop && width >= height;
  const int scene_height = std::max(1, static_cast<int>(std::lround(height * scale)));
  const int scene_width =
      square ? scene_height : std::max(1, static_cast<int>(std::lround(width * scale)));

  if (!colour_) {
    colour_ = vtkSmartPointer<vtkTextureObject>::New();
    colour_->SetContext(window);
  }
  if (colour_->GetWidth() != static_cast<unsigned>(scene_width) ||
      colour_->GetHeight() != static_cast<unsigned>(scene_height)) {
    colour_->Create2D(static_cast<unsigned>(scene_width), static_cast<unsigned>(scene_height), 4,
                      VTK_UNSIGNED_CHAR, false);
  }
  colour_->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
  colour_->SetMagnificationFilter(vtkTextureObject::Linear);
  colour_->SetWrapS(vtkTextureObject::ClampToEdge);
  colour_->SetWrapT(vtkTextureObject::ClampToEdge);
  if (!depth_) {
    depth_ = vtkSmartPointer<vtkTextureObject>::New();
    depth_->SetContext(window);
  }
  if (depth_->GetWidth() != static_cast<unsigned>(scene_width) ||
      depth_->GetHeight() != static_cast<unsigned>(scene_height)) {
    depth_->AllocateDepth(static_cast<unsigned>(scene_width), static_cast<unsigned>(scene_height),
                          vtkTextureObject::Float32);
  }
  if (!framebuffer_) {
    framebuffer_ = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    framebuffer_->SetContext(window);
  }

  // The scene into the colour and depth textures at their size, through the renderer's own
  // camera with the textures' aspect ratio (vtkDepthImageProcessingPass::RenderDelegate would
  // render through a copy of the camera that drops an explicit aspect ratio).
  vtkCamera* camera = renderer->GetActiveCamera();
  const bool explicit_aspect = camera->GetUseExplicitAspectRatio();
  const double explicit_ratio = camera->GetExplicitAspectRatio();
  camera->SetUseExplicitAspectRatio(true);
  camera->SetExplicitAspectRatio(static_cast<double>(scene_width) / scene_height);
  gl->PushFramebufferBindings();
  vtkRenderState scene(renderer);
  scene.SetPropArrayAndCount(state->GetPropArray(), state->GetPropArrayCount());
  scene.SetFrameBuffer(framebuffer_);
  framebuffer_->Bind();
  framebuffer_->AddColorAttachment(0, colour_);
  framebuffer_->ActivateDrawBuffer(0);
  framebuffer_->AddDepthAttachment(depth_);
  framebuffer_->StartNonOrtho(scene_width, scene_height);
  DelegatePass->Render(&scene);
  NumberOfRenderedProps += DelegatePass->GetNumberOfRenderedProps();
  gl->PopFramebufferBindings();
  camera->SetExplicitAspectRatio(explicit_ratio);
  camera->SetUseExplicitAspectRatio(explicit_aspect);

  if (!quad_) {
    std::string fragment = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(fragment, "//VTK::FSQ::Decl", kDeclarations);
    vtkShaderProgram::Substitute(fragment, "//VTK::FSQ::Impl", kBody);
    quad_ = std::make_unique<vtkOpenGLQuadHelper>(window, nullptr, fragment.c_str(), nullptr);
  } else {
    window->GetShaderCache()->ReadyShaderProgram(quad_->Program);
  }
  vtkShaderProgram* program = quad_->Program;
  if (program == nullptr || !program->GetCompiled()) {
    vtkErrorMacro("the endoscope lens shader did not compile");
    return;
  }

  vtkOpenGLState::ScopedglEnableDisable blend(gl, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depth_test(gl, GL_DEPTH_TEST);
  gl->vtkglDisable(GL_BLEND);
  gl->vtkglDisable(GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissor_test(gl, GL_SCISSOR_TEST);
  gl->vtkglEnable(GL_SCISSOR_TEST);
  // The composite at no more than twice the scene's resolution (a coarser scene has no finer
  // detail to resample), drawn into a texture and stretched onto the view by a linear blit; at
  // full size straight into the view.
  const double composite_scale = std::min(1.0, 2.0 * scale);
  const int out_width = composite_scale < 1.0
                            ? std::max(1, static_cast<int>(std::lround(width * composite_scale)))
                            : width;
  const int out_height = composite_scale < 1.0
                             ? std::max(1, static_cast<int>(std::lround(height * composite_scale)))
                             : height;
  const bool reduced = out_width < width || out_height < height;
  const int out_x = reduced ? 0 : origin[0], out_y = reduced ? 0 : origin[1];
  if (reduced) bind_composite(window, out_width, out_height);
  gl->vtkglViewport(out_x, out_y, out_width, out_height);
  gl->vtkglScissor(out_x, out_y, out_width, out_height);
  if (square || reduced) {
    // Black outside the field's square (a clear costs little), the shader only inside it.
    gl->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
    gl->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
  if (square) gl->vtkglScissor(out_x + (out_width - out_height) / 2, out_y, out_height, out_height);

  colour_->Activate();
  // The depth-of-field blur reads coarser levels: rebuild them from this frame (on the GPU).
  glGenerateMipmap(GL_TEXTURE_2D);
  depth_->Activate();
  program->SetUniformi("colour", colour_->GetTextureUnit());
  program->SetUniformi("depth", depth_->GetTextureUnit());
  program->SetUniformf("aspect", static_cast<float>(width) / static_cast<float>(height));
  program->SetUniformf("sceneAspect",
                       static_cast<float>(scene_width) / static_cast<float>(scene_height));
  const double* range = renderer->GetActiveCamera()->GetClippingRange();
  program->SetUniformf("nearPlane", static_cast<float>(range[0]));
  program->SetUniformf("farPlane", static_cast<float>(range[1]));
  program->SetUniformf("distortion", static_cast<float>(distortion));
  program->SetUniformf("focusDioptres", static_cast<float>(1.0 / focus_distance));
  program->SetUniformf("blurPerDioptre", static_cast<float>(blur_per_dioptre));
  program->SetUniformf("maxBlur", static_cast<float>(max_blur));
  program->SetUniformf("texelsPerPixel",
                       static_cast<float>(scene_height) / static_cast<float>(out_height));
  program->SetUniformi("fieldStop", field_stop ? 1 : 0);
  program->SetUniformf("hazeDensity", static_cast<float>(std::max(0.0, haze_density)));
  program->SetUniformf("lensFog", static_cast<float>(std::clamp(lens_fog, 0.0, 1.0)));
  const float haze[3] = {static_cast<float>(haze_colour[0]), static_cast<float>(haze_colour[1]),
                         static_cast<float>(haze_colour[2])};
  program->SetUniform3f("hazeColour", haze);
  quad_->Render();
  depth_->Deactivate();
  colour_->Deactivate();
  gl->vtkglViewport(origin[0], origin[1], width, height);
  gl->vtkglScissor(origin[0], origin[1], width, height);
  if (reduced) {
    gl->PopFramebufferBindings();  // the view's framebuffer again, drawn into by the blit
    // With the field stop only the field's square is stretched; the rest is cleared black.
    int from[4] = {0, 0, out_width, out_height};
    int to[4] = {origin[0], origin[1], origin[0] + width, origin[1] + height};
    if (square) {
      gl->vtkglClearColor(0.0, 0.0, 0.0, 1.0);
      gl->vtkglClear(GL_COLOR_BUFFER_BIT);
      from[0] = (out_width - out_height) / 2;
      from[2] = from[0] + out_height;
      to[0] = origin[0] + (width - height) / 2;
      to[2] = to[0] + height;
    }
    gl->PushReadFramebufferBinding();
    composite_framebuffer_->Bind(GL_READ_FRAMEBUFFER);
    gl->vtkglBlitFramebuffer(from[0], from[1], from[2], from[3], to[0], to[1], to[2], to[3],
                             GL_COLOR_BUFFER_BIT, GL_LINEAR);
    gl->PopReadFramebufferBinding();
  }
}

void EndoscopeLensPass::bind_composite(vtkOpenGLRenderWindow* window, int width, int height) {
  if (!composite_) {
    composite_ = vtkSmartPointer<vtkTextureObject>::New();
    composite_->SetContext(window);
    composite_framebuffer_ = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    composite_framebuffer_->SetContext(window);
  }
  if (composite_->GetWidth() != static_cast<unsigned>(width) ||
      composite_->GetHeight() != static_cast<unsigned>(height)) {
    composite_->Create2D(static_cast<unsigned>(width), static_cast<unsigned>(height), 4,
                         VTK_UNSIGNED_CHAR, false);
    composite_->SetMinificationFilter(vtkTextureObject::Linear);
    composite_->SetMagnificationFilter(vtkTextureObject::Linear);
  }
  window->GetState()->PushFramebufferBindings();
  composite_framebuffer_->Bind();
  composite_framebuffer_->AddColorAttachment(0, composite_);
  composite_framebuffer_->ActivateDrawBuffer(0);
}

void EndoscopeLensPass::ReleaseGraphicsResources(vtkWindow* window) {
  Superclass::ReleaseGraphicsResources(window);
  quad_.reset();
  if (framebuffer_) framebuffer_->ReleaseGraphicsResources(window);
  if (colour_) colour_->ReleaseGraphicsResources(window);
  if (depth_) depth_->ReleaseGraphicsResources(window);
  if (composite_framebuffer_) composite_framebuffer_->ReleaseGraphicsResources(window);
  if (composite_) composite_->ReleaseGraphicsResources(window);
}

}  // namespace viscera::view
