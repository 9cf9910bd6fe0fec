// `reconstruct` (SRAA-style): the pass on hand-written sub-samples (depth and normal written per
// sample into the plugin's prepass), and the method through the host's own model prepass.
#include "test_support.h"

#include <algorithm>
#include <cmath>

using namespace testing_support;

namespace {

constexpr int kWidth = 16, kHeight = 8;

// The display byte of display bytes a and b mixed in linear light, `shareOfA` of a.
float linearMix(float a, float b, float shareOfA) {
  return linearToSrgb(shareOfA * srgbToLinear(a / 255.0f) + (1.0f - shareOfA) * srgbToLinear(b / 255.0f)) * 255.0f;
}

// Whether any of the plugin's warnings so far contains `text`.
bool warned(const retroaa::Plugin& plugin, const std::string& text) {
  const std::vector<std::string> warnings = plugin.warnings();
  return std::any_of(warnings.begin(), warnings.end(),
                     [&text](const std::string& w) { return w.find(text) != std::string::npos; });
}

// The host's single-sample results by hand (display, depth, normal per pixel), then the plugin's pass.
// The display is the host's RGBA8 texture, or one of `displayFormat` in its place.
struct ReconstructFixture {
  SyntheticFrame frame{kWidth, kHeight};
  std::unique_ptr<StandInDisplay> standIn;  // only for a display of another format
  GLuint display = 0;                       // the host's, or standIn's
  std::unique_ptr<retroaa::Plugin> plugin;

  ReconstructFixture(const std::vector<uint8_t>& pixels, const std::vector<float>& pixelDepth, float tolerance = 2.0f,
                     int searchRadius = retroaa::Config{}.reconstructSearchRadius, GLenum displayFormat = GL_RGBA8,
                     bool compute = false, bool normalsInViewSpace = true,
                     retroaa::DisplayEncoding displayEncoding = retroaa::DisplayEncoding::DisplayEncoded) {
    const host::HostTargets& t = frame.renderer->targets();
    retroaa::Description description;
    description.config.method = retroaa::Method::Reconstruct;
    description.config.samples = 4;
    description.config.reconstructTolerance = tolerance;
    description.config.reconstructSearchRadius = searchRadius;
    description.config.reconstructCompute = compute;
    description.layout = patch::describeHostGBuffer(t);
    description.layout.normalsInViewSpace = normalsInViewSpace;
    description.layout.displayEncoding = displayEncoding;
    display = t.displayTexture;
    if (displayFormat != GL_RGBA8) {
      standIn = std::make_unique<StandInDisplay>(displayFormat, kWidth, kHeight);
      standIn->describeIn(description.layout);
      display = standIn->texture;
    }
    auto created = retroaa::Plugin::create(description);
    if (!created) throw std::runtime_error(created.error().message);
    plugin = std::move(created.value());
    glTextureSubImage2D(display, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    std::vector<uint32_t> depth(kWidth * kHeight);
    for (size_t i = 0; i < depth.size(); ++i) depth[i] = uint32_t(double(pixelDepth[i]) * 0xFFFFFF) << 8;
    glTextureSubImage2D(t.depthStencil, 0, 0, 0, kWidth, kHeight, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, depth.data());
    const std::vector<glm::vec4> normals(kWidth * kHeight, glm::vec4(0, 0, 1, 0.5f));
    glTextureSubImage2D(t.normal, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, normals.data());
  }
  ~ReconstructFixture() { plugin.reset(); }                      // before the display it filters
  void setPixelNormals(const std::vector<glm::vec4>& normals) {  // the host's, (x, y, z, gloss) per pixel
    glTextureSubImage2D(frame.renderer->targets().normal, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, normals.data());
  }
  // `body` sets gl_FragDepth and outNormal of each sub-sample from x and position.
  std::vector<uint8_t> run(const std::string& body) {
    return runPrepassFilter(*plugin, display, kWidth, kHeight, body);
  }
};

std::vector<uint8_t> noise() {
  std::vector<uint8_t> pixels(kWidth * kHeight * 4);
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t((i * 2654435761u) >> 13);
  return pixels;
}

// The wire tests' frame: background (display 30, depth 1) everywhere but one pixel of the wire's row,
// which the host shaded (display 200) at `shadedDepth`.
constexpr int kWireRow = 3, kWireColumn = 12;
struct WireFrame {
  std::vector<uint8_t> display = std::vector<uint8_t>(kWidth * kHeight * 4, 255);
  std::vector<float> depth = std::vector<float>(kWidth * kHeight, 1.0f);
};
WireFrame wireFrame(float shadedDepth) {
  WireFrame frame;
  const int shaded = kWireRow * kWidth + kWireColumn;
  for (int i = 0; i < kWidth * kHeight; ++i)
    for (int c = 0; c < 3; ++c) frame.display[size_t(i) * 4 + c] = i == shaded ? 200 : 30;
  frame.depth[shaded] = shadedDepth;
  return frame;
}

// Left of column 8 a surface (display 200, depth 0.5), right of it background (display 30, depth 1).
WireFrame halfSurfaceFrame() {
  WireFrame frame;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      for (int c = 0; c < 3; ++c) frame.display[size_t(y * kWidth + x) * 4 + c] = x < 8 ? 200 : 30;
      frame.depth[size_t(y * kWidth + x)] = x < 8 ? 0.5f : 1.0f;
    }
  return frame;
}

// The wire's row rebuilt from its shaded pixel: that pixel as shaded, every pixel within `radius`
// columns of it a quarter of its colour (one sub-sample in four, in linear light), the rest background.
void expectWireRebuiltWithin(const std::vector<uint8_t>& out, int radius) {
  const float quarter = linearMix(200.0f, 30.0f, 0.25f);
  for (int x = 0; x < kWidth; ++x) {
    const int distance = std::abs(x - kWireColumn);
    const float expected = distance == 0 ? 200.0f : distance <= radius ? quarter : 30.0f;
    EXPECT_NEAR(out[size_t(kWireRow * kWidth + x) * 4], expected, 1.0) << "radius " << radius << ", column " << x;
  }
}

}  // namespace

TEST(Reconstruct, AFlatInteriorIsReturnedExactly) {
  // Noise for texture detail: every sub-sample lies on its pixel's surface, so nothing is blended.
  const std::vector<uint8_t> input = noise();
  ReconstructFixture fixture(input, std::vector<float>(kWidth * kHeight, 0.5f));
  EXPECT_EQ(fixture.run("gl_FragDepth = 0.5; outNormal = vec4(0.0, 0.0, 1.0, 0.5);"), input);
}

TEST(Reconstruct, ADepthStepBelowTheToleranceIsNoEdge) {
  // Columns alternate between two depths 7e-6 relative apart (log depth buffer, near 0.1, far 100:
  // depth-buffer 0.5 and 0.500001), and each pixel's right half lies at its neighbours' depth. Within
  // c = 2 footprints that is one surface and nothing changes; with c = 0 the right halves are rebuilt
  // from the neighbours they match.
  const std::vector<uint8_t> input = noise();
  std::vector<float> depth(kWidth * kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) depth[i] = (i % kWidth) % 2 ? 0.500001f : 0.5f;
  const char* body =
      "bool odd = x % 2 == 1; float own = odd ? 0.500001 : 0.5, other = odd ? 0.5 : 0.500001;"
      " gl_FragDepth = position.x > 0.5 ? other : own; outNormal = vec4(0.0, 0.0, 1.0, 0.5);";
  ReconstructFixture tolerant(input, depth, 2.0f);
  EXPECT_EQ(tolerant.run(body), input);
  ReconstructFixture strict(input, depth, 0.0f);
  EXPECT_NE(strict.run(body), input) << "with no tolerance the same step is an edge";
}

TEST(Reconstruct, AFloorAtAGrazingAngleKeepsItsTextureAndASilhouetteOnItIsStillRebuilt) {
  // A floor at a grazing angle: 1 / depth (affine in the screen across a plane) falls up the rows, from
  // 1.18 m at row 0's centre to 6.7 m at row 7's. A sub-sample 3/8 px from its pixel's centre lies up to a
  // quarter deeper or nearer than the centre, beyond Eq. 1's two footprints (about 18 % here); on the
  // plane its neighbours continue it is the pixel's own surface, and the texture comes back bit for bit
  // (rebuilt from the rows around it, a start line's checks smeared: STK's black_forest). A wall 0.5 m
  // away standing on it left of x = 7.6 still makes column 7 an edge.
  const auto toBuffer = [](float metres) { return std::log2(metres / 0.1f) / std::log2(1000.0f); };  // log depth
  std::vector<float> floorDepth(kWidth * kHeight), withWall(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      floorDepth[size_t(y * kWidth + x)] = toBuffer(1.0f / (0.9f - 0.1f * (float(y) + 0.5f)));
      withWall[size_t(y * kWidth + x)] = x < 8 ? toBuffer(0.5f) : floorDepth[size_t(y * kWidth + x)];
    }
  const std::string floorBody =
      "float floorDepth = log2(1.0 / (0.9 - 0.1 * (float(y) + position.y)) / 0.1) / log2(1000.0);"
      " outNormal = vec4(0.0, 0.0, 1.0, 0.5);";
  const std::vector<uint8_t> input = noise();
  ReconstructFixture floor(input, floorDepth);
  EXPECT_EQ(floor.run(floorBody + " gl_FragDepth = floorDepth;"), input);
  ReconstructFixture wall(input, withWall);
  const std::vector<uint8_t> out = wall.run(floorBody + " gl_FragDepth = float(x) + position.x < 7.6 ? " +
                                            std::to_string(toBuffer(0.5f)) + " : floorDepth;");
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = size_t(y * kWidth + x) * 4;
      const bool same = std::equal(out.begin() + long(i), out.begin() + long(i) + 3, input.begin() + long(i));
      EXPECT_EQ(same, x != 7) << "row " << y << ", column " << x << (x == 7 ? ": the wall's silhouette" : "");
    }
}

TEST(Reconstruct, AHalfCoveredSilhouettePixelMixesItsNeighboursByCoverage) {
  // Left of x = 7.6 a surface (display 200), right of it background (display 30). Column 7's centre is on
  // the surface; its sub-samples right of 0.6 see the background: half of them at 4× (llvmpipe's and
  // the standard pattern, x = 0.375, 0.875, 0.125, 0.625). The mix is the same whether the texture unit
  // decodes the display (RGBA8, read through its sRGB view; an sRGB display's RGBA8 stand-in) or the
  // shader does (a half-float display has no sRGB twin).
  const WireFrame half = halfSurfaceFrame();
  const std::vector<uint8_t>& display = half.display;
  const std::vector<float>& depth = half.depth;
  const float mixed = linearMix(200.0f, 30.0f, 0.5f);
  // The compute pass too (reconstruct_compute=on): it writes through image stores, which a three-channel
  // display does not take; there it runs the full-screen pass and says so.
  for (bool compute : {false, true})
    for (GLenum format : {GL_RGBA8, GL_SRGB8_ALPHA8, GL_RGBA16F, GL_RGB8}) {
      ReconstructFixture fixture(display, depth, 2.0f, retroaa::Config{}.reconstructSearchRadius, format, compute);
      const std::vector<uint8_t> out =
          fixture.run("gl_FragDepth = float(x) + position.x >= 7.6 ? 1.0 : 0.5; outNormal = vec4(0.0, 0.0, 1.0, 0.5);");
      for (int y = 0; y < kHeight; ++y) {
        EXPECT_NEAR(out[(y * kWidth + 7) * 4], mixed, 1.0)
            << std::hex << format << std::dec << (compute ? " compute" : "") << " row " << y
            << ": half surface, half background";
        EXPECT_EQ(out[(y * kWidth + 6) * 4], 200) << "row " << y;
        EXPECT_EQ(out[(y * kWidth + 8) * 4], 30) << "row " << y;
      }
      EXPECT_EQ(
          warned(*fixture.plugin,
                 "reconstruct_compute=on: the display's format takes no image stores; using the full-screen pass"),
          compute && format == GL_RGB8)
          << std::hex << format;
      EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    }
}

TEST(Reconstruct, ALinearDisplayIsMixedAsStored) {
  // The half-covered column of the test above, on a display the layout says holds linear light (a window
  // shown as stored): the mix is the plain mean of the stored values, not of their sRGB decodings.
  const WireFrame half = halfSurfaceFrame();
  const std::vector<uint8_t>& display = half.display;
  const std::vector<float>& depth = half.depth;
  for (GLenum format : {GL_RGBA8, GL_RGBA16F}) {
    ReconstructFixture fixture(display, depth, 2.0f, retroaa::Config{}.reconstructSearchRadius, format, false, true,
                               retroaa::DisplayEncoding::Linear);
    const std::vector<uint8_t> out =
        fixture.run("gl_FragDepth = float(x) + position.x >= 7.6 ? 1.0 : 0.5; outNormal = vec4(0.0, 0.0, 1.0, 0.5);");
    for (int y = 0; y < kHeight; ++y) {
      EXPECT_NEAR(out[(y * kWidth + 7) * 4], 115.0, 1.0) << std::hex << format << std::dec << " row " << y;
      EXPECT_EQ(out[(y * kWidth + 6) * 4], 200);
      EXPECT_EQ(out[(y * kWidth + 8) * 4], 30);
    }
  }
}

TEST(Reconstruct, TheComputePassWritesTheSameImageAsTheFullScreenPass) {
  // The demo frame, after and before tonemapping, at several search radii: byte for byte. The pass's
  // fragment invocations tell which of the two ran (the compute pass draws nothing).
  PatchedHost host("default", 96, 72);
  for (const std::string options : {"", "@reconstruct_before_tonemap=on", "@reconstruct_search_radius=1"}) {
    const std::string method = "reconstruct@measure_gpu_time=on" + options;
    const app::DisplayImage fullScreen = host.render(method);
    const retroaa::Stats fullScreenStats = host.hooks->plugin().waitForStats();
    const app::DisplayImage compute = host.render(method + "@reconstruct_compute=on");
    const retroaa::Stats computeStats = host.hooks->plugin().waitForStats();
    EXPECT_EQ(compute.rgb, fullScreen.rgb) << method;
    EXPECT_NE(compute.rgb, host.render("off").rgb) << method;
    auto invocations = [](const retroaa::Stats& stats) {
      for (const retroaa::PassStats& pass : stats.passes)
        if (pass.name == "reconstruct") return int64_t(pass.fragmentInvocations);
      return int64_t(-1);
    };
    EXPECT_GE(invocations(fullScreenStats), 96 * 72) << method;
    EXPECT_EQ(invocations(computeStats), 0) << method;
    EXPECT_TRUE(host.hooks->lastError().empty()) << host.hooks->lastError();
  }
  // The compute pass writes through image unit 0; a host's own binding there survives it.
  const GLuint hostImage = host.renderer->targets().color;
  glBindImageTexture(0, hostImage, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
  host.render("reconstruct@reconstruct_compute=on");
  GLint bound = 0;
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &bound);
  EXPECT_EQ(GLuint(bound), hostImage);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
}

TEST(Reconstruct, ASubSampleOnTheOtherFaceOfAnEdgeSkipsTheFaceItIsPerpendicularTo) {
  // A box edge at one depth: columns up to 8 are face A (normal facing the camera, display 200), columns
  // from 9 face B (normal 87° from A's, display 30), and column 7's sub-samples right of 0.6 lie on B.
  // Ring 1 around column 7 holds only A; B's normal agrees with A's to cos⁸ 87° ≈ 4e-11, a faint
  // match, so those sub-samples look one ring farther and take B's colour from column 9: column 7
  // becomes the half-and-half mix. (Taking the faint match made column 7 all A, 200.)
  std::vector<uint8_t> display(kWidth * kHeight * 4, 255);
  std::vector<glm::vec4> normals(kWidth * kHeight);
  const glm::vec3 faceB = glm::normalize(glm::vec3(1.0f, 0.0f, 0.05f));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      for (int c = 0; c < 3; ++c) display[(y * kWidth + x) * 4 + c] = x <= 8 ? 200 : 30;
      normals[y * kWidth + x] = x <= 8 ? glm::vec4(0, 0, 1, 0.5f) : glm::vec4(faceB, 0.5f);
    }
  ReconstructFixture fixture(display, std::vector<float>(kWidth * kHeight, 0.5f));
  fixture.setPixelNormals(normals);
  const std::vector<uint8_t> out = fixture.run(
      "bool onB = x >= 9 || (x == 7 && position.x > 0.6); gl_FragDepth = 0.5;"
      " outNormal = onB ? vec4(normalize(vec3(1.0, 0.0, 0.05)), 0.5) : vec4(0.0, 0.0, 1.0, 0.5);");
  const float mixed = linearMix(200.0f, 30.0f, 0.5f);
  for (int y = 0; y < kHeight; ++y) {
    EXPECT_NEAR(out[(y * kWidth + 7) * 4], mixed, 1.0) << "row " << y << ": half A, half B";
    EXPECT_EQ(out[(y * kWidth + 8) * 4], 200) << "row " << y;
    EXPECT_EQ(out[(y * kWidth + 9) * 4], 30) << "row " << y;
  }
}

TEST(Reconstruct, NormalsInAnySpaceKeepTheirSignInThePrepass) {
  // World-space normals (normalsInViewSpace off): faces A and B at one depth differ only in the sign of
  // z, as a view-space normal never does. Kept as x and y alone (RG16F, z rebuilt as positive), B's
  // sub-samples would match A and column 7 stay A's; kept whole, they take B's colour from column 9:
  // column 7 is the half-and-half mix.
  std::vector<uint8_t> display(kWidth * kHeight * 4, 255);
  std::vector<glm::vec4> normals(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      for (int c = 0; c < 3; ++c) display[(y * kWidth + x) * 4 + c] = x <= 8 ? 200 : 30;
      normals[y * kWidth + x] = glm::vec4(0.6f, 0.0f, x <= 8 ? 0.8f : -0.8f, 0.5f);
    }
  ReconstructFixture fixture(display, std::vector<float>(kWidth * kHeight, 0.5f), 2.0f,
                             retroaa::Config{}.reconstructSearchRadius, GL_RGBA8, false, /*normalsInViewSpace=*/false);
  fixture.setPixelNormals(normals);
  const std::vector<uint8_t> out = fixture.run(
      "bool onB = x >= 9 || (x == 7 && position.x > 0.6); gl_FragDepth = 0.5;"
      " outNormal = vec4(0.6, 0.0, onB ? -0.8 : 0.8, 0.5);");
  EXPECT_EQ(fixture.plugin->stats().bytesHeld, uint64_t(kWidth * kHeight) * (4u * 4u + 4u * 8u + 4u + 1u))
      << "the whole RGBA16F normal per sample";
  const float mixed = linearMix(200.0f, 30.0f, 0.5f);
  for (int y = 0; y < kHeight; ++y) {
    EXPECT_NEAR(out[(y * kWidth + 7) * 4], mixed, 1.0) << "row " << y << ": half A, half B";
    EXPECT_EQ(out[(y * kWidth + 9) * 4], 30) << "row " << y;
  }
}

TEST(Reconstruct, AWireNoNearbyPixelCentreHitsIsRebuiltFromOneAlongIt) {
  // Background (display 30) everywhere; in row 3 a wire in front of it that only the sub-samples at
  // y = 0.625 see, except in column 12, where it bends across the whole pixel and the host shaded it
  // (display 200). With search radius 4 every wire sub-sample within 4 pixels of column 12 takes its
  // colour, one of four sub-samples: a quarter of the wire, in linear light. Radius 1 reaches only the
  // adjacent columns; beyond the radius the pixel stays as shaded.
  const WireFrame frame = wireFrame(0.5f);
  const char* body =
      "bool wire = y == 3 && (abs(position.y - 0.625) < 0.05 || x == 12);"
      " gl_FragDepth = wire ? 0.5 : 1.0; outNormal = vec4(0.0, 0.0, 1.0, 0.5);";
  for (int radius : {1, 4}) {
    ReconstructFixture fixture(frame.display, frame.depth, 2.0f, radius);
    const std::vector<uint8_t> out = fixture.run(body);
    expectWireRebuiltWithin(out, radius);
    EXPECT_EQ(out[size_t(2 * kWidth + 5) * 4], 30) << "rows off the wire stay as shaded";
  }
}

TEST(Reconstruct, AWireRecedingFromTheCameraIsRebuiltFromAPixelCentreRingsAlongIt) {
  // The wire of the test above, now receding to the left: each column 7 % deeper than the next (depth
  // buffer 0.01 apart, log depth, near 0.1, far 100). One pixel's footprint is 5 % of the depth here
  // (hfov 0.8 over 16 columns), so c = 2 holds the adjacent column (7 %) but not the one two away
  // (15 %): beyond ring 1 the tolerance is wider, and every wire sub-sample within the radius takes
  // column 12's colour, as on a wire facing the camera.
  const WireFrame frame = wireFrame(0.5f);
  const char* body =
      "bool wire = y == 3 && (abs(position.y - 0.625) < 0.05 || x == 12);"
      " gl_FragDepth = wire ? 0.5 + 0.01 * float(12 - x) : 1.0; outNormal = vec4(0.0, 0.0, 1.0, 0.5);";
  ReconstructFixture fixture(frame.display, frame.depth, 2.0f, 4);
  expectWireRebuiltWithin(fixture.run(body), 4);
}

TEST(Reconstruct, AWireTakesNoColourFromASurfaceFarBehindItHoweverFarItSearches) {
  // The wire of the tests above at depth buffer 0.5, but the one pixel centre in its row that is not
  // background, column 12, shows another surface of the same normal 7.9 times as deep (depth buffer
  // 0.8). The wider tolerance beyond ring 1 (16 × Eq. 1's, 2.6 times as deep here) still tells them
  // apart: no wire sub-sample takes its colour, and every pixel keeps its own.
  const WireFrame frame = wireFrame(0.8f);
  const char* body =
      "bool far = y == 3 && x == 12, wire = y == 3 && abs(position.y - 0.625) < 0.05;"
      " gl_FragDepth = far ? 0.8 : wire ? 0.5 : 1.0; outNormal = vec4(0.0, 0.0, 1.0, 0.5);";
  ReconstructFixture fixture(frame.display, frame.depth, 2.0f, 4);
  const std::vector<uint8_t> out = fixture.run(body);
  for (int x = 0; x < kWidth; ++x)
    EXPECT_EQ(out[size_t(kWireRow * kWidth + x) * 4], x == kWireColumn ? 200 : 30) << "column " << x;
}

TEST(Reconstruct, LightsOncePerPixelAndHoldsAQuarterOfResolvesMemory) {
  PatchedHost host("default", 64, 48);
  const app::DisplayImage off = host.render("off");
  const app::DisplayImage rebuilt = host.render("reconstruct");
  const retroaa::Stats stats = host.hooks->plugin().waitForStats();
  EXPECT_EQ(stats.evaluationsPerPixel(), 1.0);
  ASSERT_EQ(stats.samples, 4);
  // D24S8 and RG16F normals × 4 samples, the post copy and the stencil of the pixels it rebuilds: 37 B/px
  // against resolve's 160.
  EXPECT_EQ(stats.bytesHeld, uint64_t(64 * 48) * (4u * 4u + 4u * 4u + 4u + 1u));
  EXPECT_EQ(host.hooks->plugin().geometryFramebuffer(), host.renderer->targets().gbufferFramebuffer);
  // Only edge pixels change: the interior of the image is the host's own.
  int changed = 0;
  for (size_t i = 0; i < off.rgb.size(); i += 3) changed += off.rgb[i] != rebuilt.rgb[i];
  EXPECT_GT(changed, 0);
  EXPECT_LT(changed, int(off.rgb.size() / 3) / 4);
  // Before tonemapping: the same pass on the light target, with a copy of it (8 B/px more).
  const app::DisplayImage radiance = host.render("reconstruct@reconstruct_before_tonemap=on");
  EXPECT_EQ(host.hooks->plugin().stats().bytesHeld, stats.bytesHeld + uint64_t(64 * 48) * 8u);
  EXPECT_EQ(host.hooks->plugin().waitForStats().evaluationsPerPixel(), 1.0);
  int changedBefore = 0;
  for (size_t i = 0; i < off.rgb.size(); i += 3) changedBefore += off.rgb[i] != radiance.rgb[i];
  EXPECT_GT(changedBefore, 0);
  EXPECT_LT(changedBefore, int(off.rgb.size() / 3) / 4);
  EXPECT_TRUE(host.hooks->lastError().empty()) << host.hooks->lastError();
  host.render("resolve");
  const uint64_t resolveBytes = host.hooks->plugin().stats().bytesHeld;
  EXPECT_LE(stats.bytesHeld * 4, resolveBytes);
  host.render("resolve+reconstruct");  // the MSAA G-buffer's depth and normals: no prepass
  EXPECT_EQ(host.hooks->plugin().prepassFramebuffer(), 0u);
}

TEST(Reconstruct, StackedAtOneSampleIsTurnedOffWithAWord) {
  // At 1× the G-buffer has no sub-samples to read (its textures are not even multisampled).
  PatchedHost host("default", 32, 24);
  const app::DisplayImage stacked = host.render("resolve+reconstruct@samples=1");
  EXPECT_TRUE(warned(host.hooks->plugin(), "reconstruct_filter needs at least 2 samples and samples=1"));
  EXPECT_EQ(stacked.rgb, host.render("resolve@samples=1").rgb);
  EXPECT_TRUE(host.hooks->lastError().empty()) << host.hooks->lastError();
}
