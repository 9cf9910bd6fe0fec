// Textured materials in both hosts: model files' own textures (external and embedded), procedural
// maps, and a ground truth that filters textures as a supersampled render would.
#include "ground_truth.h"
#include "second_renderer.h"
#include "test_support.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace testing_support;

namespace {

const char* kBoxTexturedGltf = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
const char* kBoxTexturedGlb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";

std::string writeScene(const std::string& name, const std::string& json) {
  const std::string path = (std::filesystem::temp_directory_path() / ("retroaa_" + name + ".json")).string();
  std::ofstream(path) << json;
  return path;
}

// A textured glTF box, framed; `material` set overrides the model's own (its textures go).
std::string boxScene(const std::string& model, const std::string& material) {
  return writeScene("textured_box", R"({"camera": "fit", "ambient": [0.3, 0.3, 0.3],
    "materials": [{"name": "grey", "albedo": [0.5, 0.5, 0.5]}],
    "objects": [{"name": "box", "model": ")" +
                                        model + "\"" +
                                        (material.empty() ? "" : R"(, "material": ")" + material + "\"") + R"(}],
    "lights": [{"type": "directional", "direction": [-0.3, -0.5, -1], "intensity": 2}]})");
}

// Pixels whose display colour is the Cesium logo's green (green well above red and blue).
int logoGreenPixels(const std::vector<uint8_t>& rgba) {
  int count = 0;
  for (size_t p = 0; p + 3 < rgba.size(); p += 4)
    if (rgba[p + 1] > 80 && rgba[p + 1] > rgba[p] + 30 && rgba[p + 1] > rgba[p + 2] + 30) ++count;
  return count;
}

}  // namespace

TEST(Textures, AGltfModelRendersWithItsOwnTexturesInBothHosts) {
  for (const char* model : {kBoxTexturedGltf, kBoxTexturedGlb}) {  // an external PNG, an embedded one
    const host::Scene textured = host::loadScene(boxScene(model, ""));
    ASSERT_EQ(textured.objects.size(), 1u);
    const host::Material& material = textured.materials[size_t(textured.objects[0].material)];
    ASSERT_TRUE(material.maps.albedo) << model;
    EXPECT_GT(material.maps.albedo->width, 0);
    const host::Scene plain = host::loadScene(boxScene(model, "grey"));
    EXPECT_FALSE(plain.materials[size_t(plain.objects[0].material)].maps.albedo);
    context();
    for (bool second : {false, true}) {
      auto display = [&](const host::Scene& scene) {
        std::unique_ptr<host::Engine> engine;
        if (second)
          engine = std::make_unique<host::SecondRenderer>(scene, 128, 96);
        else
          engine = std::make_unique<host::Renderer>(scene, 128, 96);
        engine->renderFrame(scene.camera);
        return engine->readDisplay();
      };
      EXPECT_GT(logoGreenPixels(display(textured)), 200) << model << (second ? " (second host)" : " (FSO host)");
      EXPECT_EQ(logoGreenPixels(display(plain)), 0) << model << (second ? " (second host)" : " (FSO host)");
    }
  }
}

TEST(Textures, AMissingTextureFileIsAClearSceneError) {
  const std::string directory = (std::filesystem::temp_directory_path() / "retroaa_missing_texture").string();
  std::filesystem::create_directories(directory);
  std::filesystem::copy_file(kBoxTexturedGltf, directory + "/BoxTextured.gltf",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file("/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured0.bin",
                             directory + "/BoxTextured0.bin", std::filesystem::copy_options::overwrite_existing);
  try {
    host::loadScene(boxScene(directory + "/BoxTextured.gltf", ""));
    FAIL() << "a model whose texture file is missing loaded";
  } catch (const host::SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("$.objects[0].model"), std::string::npos) << message;
    EXPECT_NE(message.find("CesiumLogoFlat.png"), std::string::npos) << message;
  }
  // A texture named in the scene that is no regular file: refused before reading (no hang on a FIFO).
  try {
    host::loadScene(writeScene("dev_zero_texture", R"({"camera": "fit",
      "materials": [{"name": "m", "albedo_map": "/dev/zero"}],
      "objects": [{"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m"}]})"));
    FAIL() << "/dev/zero loaded as a texture";
  } catch (const host::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("$.materials[0].albedo_map"), std::string::npos) << e.what();
  }
}

TEST(Textures, TheScenesTexturesTogetherStayBounded) {
  // Nine 2048² procedural sets would hold 576 MiB: the ninth is refused before it is generated.
  std::string materials;
  for (int i = 0; i < 9; ++i)
    materials += std::string(i ? ", " : "") + R"({"name": "m)" + std::to_string(i) +
                 R"(", "procedural": {"pattern": "checker", "texels": 2048}})";
  try {
    host::loadScene(writeScene("texture_budget", R"({"camera": "fit", "materials": [)" + materials + R"(],
      "objects": [{"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m0"}]})"));
    FAIL() << "576 MiB of textures loaded";
  } catch (const host::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("$.materials[8].procedural"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("512 MiB"), std::string::npos) << e.what();
  }
}

TEST(Textures, ProceduralMapsAreDeterministicAndDifferBySeed) {
  auto scene = [](int seed) {
    return host::loadScene(writeScene("procedural_" + std::to_string(seed), R"({"camera": "fit",
      "materials": [{"name": "m", "procedural": {"pattern": "panels", "texels": 64, "seed": )" +
                                                                                std::to_string(seed) +
                                                                                R"(, "glow": 0.5}}],
      "objects": [{"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m"}]})"));
  };
  const host::Scene a = scene(1), b = scene(1), c = scene(2);
  const host::MaterialMaps &ma = a.materials[0].maps, &mb = b.materials[0].maps, &mc = c.materials[0].maps;
  ASSERT_TRUE(ma.albedo && ma.normal && ma.specular && ma.emissive);
  EXPECT_EQ(ma.albedo->rgba, mb.albedo->rgba);
  EXPECT_EQ(ma.normal->rgba, mb.normal->rgba);
  EXPECT_NE(ma.albedo->rgba, mc.albedo->rgba);
  // Every normal-map texel is a unit vector facing out of the surface.
  for (size_t t = 0; t < ma.normal->rgba.size(); t += 4) {
    const glm::vec3 n = glm::vec3(ma.normal->rgba[t], ma.normal->rgba[t + 1], ma.normal->rgba[t + 2]) / 127.5f - 1.0f;
    ASSERT_NEAR(glm::length(n), 1.0f, 0.02f);
    ASSERT_GT(n.z, 0.0f);
  }
}

TEST(Textures, GroundTruthFiltersTexturesPerSupersampleAndConverges) {
  // A mipmapped checkerboard on a plane seen at a grazing angle: the checks run from several pixels
  // wide at the bottom to far below a pixel at the horizon.
  const std::string scene = writeScene("grazing_checker", R"({"camera": {"position": [0, 0.6, 6], "target": [0, 0, -20],
      "fov_y_deg": 50}, "star_density": 0, "ambient": [1, 1, 1],
    "materials": [{"name": "checker", "albedo": [1, 1, 1], "specular": [0, 0, 0], "gloss": 0,
                   "procedural": {"pattern": "checker", "texels": 256}, "uv_scale": 0.25}],
    "objects": [{"generator": {"type": "plane", "size": [200, 1, 200]}, "material": "checker"}]})");
  PatchedHost host(scene, 96, 72);
  auto truth = [&](int s, host::TextureFootprint footprint) {
    const host::GroundTruth gt = host::renderGroundTruth(*host.renderer, host.scene.camera, s, footprint);
    return app::DisplayImage::fromRgba8(gt.width, gt.height, gt.display);
  };
  const app::DisplayImage gt8 = truth(8, host::TextureFootprint::Supersample);
  const app::DisplayImage gt16 = truth(16, host::TextureFootprint::Supersample);
  const double converged = app::compare(gt8, gt16, {}).psnrDb;
  EXPECT_GE(converged, 40.0);
  // Filtering at the pixel's footprint instead blurs each supersample as much as the whole pixel:
  // further from the 16×16 truth than the 8×8 one is.
  const app::DisplayImage pixelFootprint = truth(8, host::TextureFootprint::Pixel);
  EXPECT_LT(app::compare(pixelFootprint, gt16, {}).psnrDb, converged - 3.0);
  // A render 4× larger (ssaa at m = 4: the host's own derivatives pick the finer level) agrees with the
  // 4×4 truth that reaches it by the bias.
  const app::DisplayImage ssaa = host.render("ssaa", [] {
    retroaa::Config c;
    c.supersample = 4;
    return c;
  }());
  const app::DisplayImage gt4 = truth(4, host::TextureFootprint::Supersample);
  const app::DisplayImage gt4Pixel = truth(4, host::TextureFootprint::Pixel);
  const double ssaaBiased = app::compare(ssaa, gt4, {}).psnrDb, ssaaPixel = app::compare(ssaa, gt4Pixel, {}).psnrDb;
  EXPECT_GT(ssaaBiased, ssaaPixel + 3.0);
  std::printf(
      "8x8 vs 16x16: %.1f dB; pixel-footprint 8x8 vs 16x16: %.1f dB; ssaa m=4 vs 4x4: %.1f dB (%.1f dB "
      "at the pixel footprint)\n",
      converged, app::compare(pixelFootprint, gt16, {}).psnrDb, ssaaBiased, ssaaPixel);
}
