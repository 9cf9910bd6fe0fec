// The host engine: context, depth encoding, scene files, model loading, the demo render, ground truth.
#include "bounded_json.h"
#include "depth_codec.h"
#include "image_io.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

using namespace testing_support;
namespace fs = std::filesystem;
namespace codec = host::depth_codec;

namespace {

std::string sceneErrorOf(const std::string& json) {
  try {
    host::parseScene(json, "test.json", ".");
  } catch (const host::SceneError& e) {
    return e.what();
  }
  return "";
}

std::string withObjects(const std::string& objects) {
  return R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [{"name": "m"}], "objects": [)" +
         objects + "]}";
}
}  // namespace

TEST(Context, IsGl45CoreWithSamplesReported) {
  const host::ContextInfo& info = context().info();
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_NE(info.version.find("4.5"), std::string::npos) << info.version;
  EXPECT_GE(info.maxSamples, 1);
  EXPECT_NE(info.summary().find("GL_MAX_SAMPLES"), std::string::npos);
}

TEST(DepthCodec, IsMonotonicAndContinuousAtTheKnee) {
  EXPECT_FLOAT_EQ(codec::encode(codec::kKnee), codec::kKnee);
  EXPECT_NEAR(codec::encode(codec::kKnee * 1.0001f), codec::kKnee * 1.0001f, 1.0f);  // continuous, slope 1/ln 2 above
  float previous = -1.0f;
  for (float d = 0.01f; d < codec::kMaxDepth; d *= 1.05f) {
    const float e = codec::encode(d);
    EXPECT_GT(e, previous) << "at " << d;
    previous = e;
  }
  EXPECT_LT(codec::encode(codec::kMaxDepth), codec::kBackgroundThreshold);
  EXPECT_TRUE(codec::isBackground(codec::kBackgroundMarker));
  EXPECT_TRUE(codec::isBackground(NAN));
  EXPECT_FALSE(codec::isBackground(codec::encode(codec::kMaxDepth)));
}

TEST(DepthCodec, Fp16RoundTripKeepsRelativePrecisionFrom1mTo1e6m) {
  double worstBelowKnee = 0, worstAboveKnee = 0;
  for (double d = 1.0; d <= 1.0e6; d *= 1.0137) {  // ~1000 depths across the range
    const float decoded = codec::decode(throughHalf(codec::encode(float(d))));
    const double relative = std::fabs(decoded - d) / d;
    (d <= codec::kKnee ? worstBelowKnee : worstAboveKnee) =
        std::max(d <= codec::kKnee ? worstBelowKnee : worstAboveKnee, relative);
  }
  EXPECT_LT(worstBelowKnee, 5.0e-4);  // FP16's own 2^-11
  EXPECT_LT(worstAboveKnee, 1.4e-3);  // ln 2 · half an FP16 ulp at 65k / knee
  // Without the encoding, FP16 would overflow past 65 504 m.
  EXPECT_TRUE(std::isinf(throughHalf(1.0e5f)));
  std::printf("depth round trip: worst relative error %.2e below the knee, %.2e above\n", worstBelowKnee,
              worstAboveKnee);
}

TEST(SceneFile, DefaultSceneHasEveryHardCase) {
  const host::Scene scene = host::loadScene("default");
  EXPECT_GE(scene.lights.size(), 17u);  // 16 point lights at least, plus the sun
  int points = 0;
  for (const host::Light& l : scene.lights) points += l.type == host::LightType::Point;
  EXPECT_GE(points, 16);
  EXPECT_GE(scene.path.frameCount(), 30);
  std::set<std::string> names;
  for (const host::Object& o : scene.objects) names.insert(o.name.substr(0, o.name.find('#')));
  for (const char* expected :
       {"near_hull", "antenna", "wire", "specular_tube", "deck", "plate_red", "plate_blue", "far_ship"})
    EXPECT_TRUE(names.count(expected)) << expected;
}

TEST(SceneFile, ErrorsNameFileFieldAndExpectation) {
  EXPECT_NE(sceneErrorOf("{not json").find("test.json: (document): not valid JSON"), std::string::npos);
  EXPECT_NE(sceneErrorOf(R"({"materials": []})").find("missing required key 'camera'"), std::string::npos);
  EXPECT_NE(sceneErrorOf(withObjects(R"({"generator": {"type": "box", "size": [1, 1]}, "material": "m"})"))
                .find("$.objects[0].generator.size: expected an array of 3 numbers"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(withObjects(R"({"generator": {"type": "box", "size": [1, 1, 1]}, "material": "nope"})"))
                .find("$.objects[0].material: no material named 'nope'"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(withObjects(R"({"generator": {"type": "torus"}, "material": "m"})"))
                .find("unknown generator 'torus'"),
            std::string::npos);
  EXPECT_NE(
      sceneErrorOf(withObjects(R"({"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m", "colour": 1})"))
          .find("$.objects[0].colour: unknown key"),
      std::string::npos);
  EXPECT_NE(sceneErrorOf(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [],
                              "position_depth": "fp16"})")
                .find("$.position_depth: unknown position depth 'fp16' (allowed: log-above-knee, fso-compressed)"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "far": 5000}, "materials": [],
                              "position_depth": "fso-compressed"})")
                .find("$.position_depth: fso-compressed needs a camera far plane beyond 100000 m"),
            std::string::npos);
  const std::string missingModel = sceneErrorOf(withObjects(R"({"model": "missing.obj", "material": "m"})"));
  EXPECT_NE(missingModel.find("$.objects[0].model: "), std::string::npos) << missingModel;
  EXPECT_NE(missingModel.find("missing.obj' is not a regular file"), std::string::npos) << missingModel;
  EXPECT_NE(sceneErrorOf(withObjects(R"({"generator": {"type": "sphere", "radius": -1}, "material": "m"})"))
                .find("expected a finite number in"),
            std::string::npos);
  try {
    host::loadScene("/nonexistent/scene.json");
    ADD_FAILURE() << "no error for a missing file";
  } catch (const host::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json: (file): cannot open"), std::string::npos);
  }
}

TEST(Scene, MoreObjectsThanTheBudgetAreRefusedNamingTheObject) {
  // Seven boxes repeated 10 000 times each: 70 000 objects, over the 65 536 a scene may hold.
  std::string objects;
  for (int i = 0; i < 7; ++i)
    objects +=
        std::string(i ? "," : "") +
        R"({"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m", "repeat": {"count": 10000, "offset": [2, 0, 0]}})";
  const std::string error = sceneErrorOf(withObjects(objects));
  EXPECT_NE(error.find("$.objects[6]: the scene exceeds 65536 objects"), std::string::npos) << error;
}

TEST(ModelLoading, ReadsObjAndGltf) {
  const host::Mesh obj = host::mergeParts(host::loadModel(testDataPath("fixtures/quad.obj")));
  EXPECT_EQ(obj.triangleCount(), 2u);
  const host::Mesh gltf = host::mergeParts(host::loadModel(testDataPath("fixtures/triangle.gltf")));
  EXPECT_EQ(gltf.triangleCount(), 1u);
  for (const host::Vertex& v : gltf.vertices) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
  EXPECT_THROW(host::loadModel(testDataPath("fixtures/not_a_model.obj")), host::ModelLoadError);
}

TEST(ModelLoading, AGltfFaceWithAnIndexPastItsVerticesIsLeftOutWithAWarning) {
  // Two triangles over three vertices, the second indexing vertex 7: assimp drops it inside its importer.
  std::vector<std::string> warnings;
  const host::Mesh mesh =
      host::mergeParts(host::loadModel(testDataPath("fixtures/index_out_of_range.gltf"), &warnings));
  EXPECT_EQ(mesh.triangleCount(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("index_out_of_range.gltf: 1 of 2 faces had out-of-range indices; they are left out"),
            std::string::npos)
      << warnings[0];
  warnings.clear();
  host::loadModel(testDataPath("fixtures/triangle.gltf"), &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
}

TEST(DemoRender, IsNeitherBlackNorSaturatedAndProbesMatch) {
  PatchedHost host("default", 320, 240);
  const app::DisplayImage image = host.render("off");
  double mean = 0;
  int saturated = 0;
  for (float v : image.rgb) {
    mean += v;
    saturated += v >= 1.0f;
  }
  mean /= image.rgb.size();
  EXPECT_GT(mean, 0.08);
  EXPECT_LT(mean, 0.7);
  EXPECT_LT(saturated, int(image.rgb.size() / 50));

  auto pixel = [&](glm::vec3 world) {
    const glm::ivec2 p = projectToPixel(host.scene.camera, world, 320, 240);
    const float* rgb = &image.rgb[(size_t(p.y) * 320 + p.x) * 3];
    return glm::vec3(rgb[0], rgb[1], rgb[2]);
  };
  const glm::vec3 redPlate = pixel({3.0f, -2.2f, 3.0f});  // the z-fighting plates: red or blue wins
  EXPECT_GT(std::max(redPlate.r, redPlate.b), 2.0f * redPlate.g);
  const glm::vec3 sky = pixel({-20.0f, 60.0f, -200.0f});
  EXPECT_GT(sky.b, sky.r);
  EXPECT_LT(sky.b, 0.4f);
  const glm::vec3 pylon = pixel({-4.5f, 3.0f, -11.5f});  // warm-coloured wall
  EXPECT_GT(pylon.r, pylon.b);
  const glm::vec3 deck = pixel({4.0f, -5.0f, -30.0f});  // dark grey, neutral
  EXPECT_NEAR(deck.r, deck.b, 0.08f);
}

TEST(DemoRender, ExrHoldsLinearRadianceConsistentWithDisplay) {
  PatchedHost host("default", 64, 48);
  host.render("off");
  const std::vector<float> radiance = host.renderer->readLight();
  for (float v : radiance) ASSERT_TRUE(std::isfinite(v));
  double maximum = 0;
  for (size_t i = 0; i < radiance.size(); i += 4) maximum = std::max<double>(maximum, radiance[i]);
  EXPECT_GT(maximum, 0.05);
}

TEST(GroundTruth, ConvergesFrom8x8To16x16) {
  PatchedHost host("default", 160, 120);
  const host::GroundTruth coarse = host.groundTruth(8);
  const host::GroundTruth fine = host.groundTruth(16);
  const auto a = app::DisplayImage::fromRgba8(160, 120, coarse.display);
  const auto b = app::DisplayImage::fromRgba8(160, 120, fine.display);
  const app::ErrorMetrics m = app::compare(a, b, app::edgeMaskFromSpread(fine.lumaStdDev));
  std::printf("ground truth 8x8 vs 16x16: PSNR %.2f dB, edge PSNR %.2f dB\n", m.psnrDb, m.edgePsnrDb);
  EXPECT_GT(m.psnrDb, 35.0);      // stated bound: 8×8 is within 35 dB of 16×16 over the frame
  EXPECT_GT(m.edgePsnrDb, 30.0);  // and 30 dB over the edge pixels
  // And the stock single-sample render is far from both: the aliasing is real.
  const app::DisplayImage off = host.render("off");
  EXPECT_LT(app::compare(off, b, {}).psnrDb, m.psnrDb - 8.0);
}

// The stars are the background's own detail, not model edges: a sky alone has edge pixels (its stars) and
// no model edges; with the demo's models, every model-edge pixel but those the stars' light changes is
// an edge pixel too, the stars' pixels are not model edges, and neither is a silhouette a star shows behind.
TEST(GroundTruth, TellsTheBackgroundsStarsFromTheModelsEdges) {
  PatchedHost sky(host::parseScene(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "objects": [],
                                      "star_density": 2})",
                                   "sky.json", "."),
                  96, 72);
  const ScoringTruth skyTruth = sky.scoringTruth(4, host::BackgroundEdges::Apart);
  const auto count = [](const std::vector<uint8_t>& mask) { return std::count(mask.begin(), mask.end(), 1); };
  ASSERT_EQ(skyTruth.modelEdges.size(), skyTruth.edges.size());
  EXPECT_GT(count(skyTruth.edges), 20) << "the stars make edge pixels";
  EXPECT_EQ(count(skyTruth.modelEdges), 0) << "a sky has no model edge";
  EXPECT_TRUE(sky.scoringTruth(4).modelEdges.empty()) << "told apart only when asked (s^2 frames more)";

  PatchedHost demo("default", 96, 72);
  const ScoringTruth truth = demo.scoringTruth(4, host::BackgroundEdges::Apart);
  size_t modelOnly = 0, both = 0;
  for (size_t p = 0; p < truth.edges.size(); ++p) {
    modelOnly += truth.modelEdges[p] && !truth.edges[p];
    both += truth.modelEdges[p] && truth.edges[p];
  }
  std::printf("demo 96x72: %ld edge pixels, %ld model edges (%zu not among the edges)\n", long(count(truth.edges)),
              long(count(truth.modelEdges)), modelOnly);
  EXPECT_GT(both, 200u);
  EXPECT_LT(modelOnly, both / 20) << "a star behind a silhouette only adds to its spread";
  EXPECT_LT(count(truth.modelEdges), count(truth.edges)) << "the demo's stars are edges, not model edges";

  // A silhouette with a star behind it is measured as the background's: every model edge left has the
  // spread it has without the stars, and some of the starless frame's edges were left out for a star.
  const host::GroundTruth gt = host::renderGroundTruth(
      *demo.renderer, demo.scene.camera, 4, host::TextureFootprint::Supersample, host::BackgroundEdges::Apart);
  const std::vector<uint8_t> geometryEdges = app::edgeMaskFromSpread(gt.modelLumaStdDev);
  size_t starBehind = 0;
  for (size_t p = 0; p < truth.modelEdges.size(); ++p) {
    starBehind += geometryEdges[p] && !truth.modelEdges[p];
    if (truth.modelEdges[p]) {
      ASSERT_NEAR(gt.lumaStdDev[p], gt.modelLumaStdDev[p], 1.0f / 512.0f) << "pixel " << p;
    }
  }
  std::printf("demo 96x72: %zu silhouette pixels with a star behind them\n", starBehind);
  EXPECT_GT(starBehind, 0u);
  EXPECT_LT(starBehind, size_t(count(geometryEdges)) / 4);
}

// The sky is the same colour at every aspect ratio (16:10 once came out black: the background was
// un-projected at the far plane, where single precision breaks down).
TEST(DemoRender, TheSkyIsSkyAtEveryAspectRatio) {
  std::vector<double> topBlue;
  for (const auto& [width, height] : {std::pair{320, 240}, {320, 200}, {384, 216}, {640, 400}}) {
    PatchedHost host("default", width, height);
    const app::DisplayImage image = host.render("off");
    double red = 0, blue = 0;
    const int rows = height / 10;  // the top tenth: sky only in the demo scene
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < width; ++x) {
        const float* rgb = &image.rgb[(size_t(y) * width + x) * 3];
        ASSERT_TRUE(std::isfinite(rgb[0]) && std::isfinite(rgb[1]) && std::isfinite(rgb[2]));
        red += rgb[0], blue += rgb[2];
      }
    red /= rows * width, blue /= rows * width;
    EXPECT_GT(blue, 0.1) << width << "x" << height << ": the sky's top rows are dark";
    EXPECT_GT(blue, 2.0 * red) << width << "x" << height;
    topBlue.push_back(blue);
  }
  for (double blue : topBlue) EXPECT_NEAR(blue, topBlue.front(), 0.03);
}

// Non-finite vertex data: a model with nothing usable is an error naming file and mesh; one with some
// usable faces loads those and warns with counts.
TEST(ModelLoading, NonFiniteVerticesAreRefusedOrLeftOutWithAWord) {
  try {
    host::loadModel(testDataPath("fixtures/non_finite.obj"));
    ADD_FAILURE() << "a model of NaN positions loaded";
  } catch (const host::ModelLoadError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("non_finite.obj: mesh 'bad': 1 of 1 triangles have non-finite positions"), std::string::npos)
        << message;
    EXPECT_NE(message.find("nothing of the model is usable"), std::string::npos) << message;
  }
  std::vector<std::string> warnings;
  const host::Mesh half = host::mergeParts(host::loadModel(testDataPath("fixtures/half_non_finite.obj"), &warnings));
  EXPECT_EQ(half.indices.size(), 3u);
  for (const host::Vertex& v : half.vertices) EXPECT_TRUE(std::isfinite(v.position.x + v.position.y + v.position.z));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("mesh 'half': 1 of 2 triangles"), std::string::npos) << warnings[0];
}

TEST(SceneFile, CameraFitFramesTheModelsAsLoaded) {
  // A 20 m box far off the origin: "fit" aims at its centre and sees all of it, filling a good part.
  const host::Scene scene = host::parseScene(R"({"camera": "fit", "materials": [{"name": "m"}], "objects": [
      {"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m",
       "transform": {"translate": [300, -40, 120], "scale": 20}}]})",
                                             "fit.json", ".");
  EXPECT_NEAR(glm::length(scene.camera.target - glm::vec3(300, -40, 120)), 0.0f, 1e-3f);
  const glm::mat4 viewProjection = scene.camera.projection(640, 480) * scene.camera.view();
  float extent = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p =
        glm::vec3(300, -40, 120) + 10.0f * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    ASSERT_GT(clip.w, 0.0f) << "corner " << corner << " behind the camera";
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    EXPECT_LE(std::fabs(ndc.x), 1.0f) << corner;
    EXPECT_LE(std::fabs(ndc.y), 1.0f) << corner;
    EXPECT_GT(ndc.z, -1.0f) << corner << " in front of the near plane";
    extent = std::max({extent, std::fabs(ndc.x), std::fabs(ndc.y)});
  }
  EXPECT_GT(extent, 0.4f) << "the box fills a sensible part of the frame";
  EXPECT_NE(sceneErrorOf(R"({"camera": "fits", "materials": [], "objects": []})")
                .find("$.camera: expected a camera object or \"fit\""),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(R"({"camera": "fit", "materials": [{"name": "m"}], "objects": []})")
                .find("$.camera: \"fit\" needs at least one object to frame"),
            std::string::npos);
}

TEST(Record, FitOrbitsACameraThatFramesTheModels) {
  const fs::path dir = fs::temp_directory_path() / "retroaa_record_fit";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.json") << R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]},
    "materials": [{"name": "m"}], "objects": [{"generator": {"type": "box", "size": [2, 2, 2]}, "material": "m",
    "transform": {"translate": [50, 0, -200]}}]})";
  const CliRun run = runCli("record --fit --keys 2 --scene " + (dir / "scene.json").string() + " --out " +
                            (dir / "path.json").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(dir / "path.json");
  const nlohmann::json path = nlohmann::json::parse(in);
  const nlohmann::json& target = path["keys"][0]["target"];
  EXPECT_NEAR(target[0].get<float>(), 50.0f, 1e-3f);
  EXPECT_NEAR(target[2].get<float>(), -200.0f, 1e-3f);
  const CliRun empty = runCli("record --fit --scene /dev/null --out " + (dir / "x.json").string());
  EXPECT_EQ(empty.exitCode, 2) << empty.output;
}

TEST(Scene, NestingBeyondThirtyTwoLevelsIsRefusedAtOnce) {
  // Under the 64 MiB cap, a file of nested arrays used to take gigabytes before its error.
  std::string nested = R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [], "comment": )";
  nested += std::string(200000, '[') + std::string(200000, ']') + "}";
  const std::string error = sceneErrorOf(nested);
  EXPECT_NE(error.find("nested more than 32 levels deep"), std::string::npos) << error.substr(0, 200);
  // A scene nested as deep as any real one still parses.
  EXPECT_EQ(sceneErrorOf(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [{"name": "m"}],
                             "objects": [], "comment": [[[[[["deep enough"]]]]]]})"),
            "");
}

TEST(Scene, TooManyObjectsAreRefusedBeforeTheDocumentIsBuilt) {
  // 100000 objects (at most 65536): counted in the text's one pass, so the error comes before any document
  // exists; the syntax error after the array proves the parser never ran. (Parsed with nlohmann-json's
  // callback, as before, 10^6 objects took 359 s and ~1 GB before this error.)
  std::string text = R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [{"name": "m"}], )"
                     R"("objects": [)";
  const std::string object = R"({"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m"})";
  for (int i = 0; i < 100000; ++i) text += (i ? ", " : "") + object;
  text += R"(], "comment": nul})";
  const std::string error = sceneErrorOf(text);
  EXPECT_NE(error.find("$.objects: has 100000 elements (at most 65536)"), std::string::npos) << error.substr(0, 200);
  // Keys and strings that look like the array do not count: a string holding brackets and commas, a nested
  // "objects" key, and an empty array.
  EXPECT_EQ(sceneErrorOf(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [{"name": "m"}],
                             "comment": {"objects": [1, 2, 3]}, "name": "objects\", [,,]",
                             "objects": [{"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m"}]})"),
            "");
  EXPECT_EQ(sceneErrorOf(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "objects": []})"), "");
}

TEST(Scene, EveryArrayAndKeySpellingIsBoundedBeforeTheDocumentIsBuilt) {
  // The root's "lights" are counted as "objects" are; a key is compared as the parser reads it (a
  // "obj\u0065cts" array of 10^6 boxes used to pass the scan: 1.00 GB); and any document holds at most
  // 4 M values wherever they lie (22 M "{}" in "lights" took 2.65 GB). Each is refused with a syntax error
  // after it, so the parser never ran.
  const std::string head = R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [{"name": "m"}], )";
  std::string lights = head + R"("lights": [)";
  for (int i = 0; i < 5000; ++i) lights += std::string(i ? ", " : "") + R"({"type": "point", "position": [0, 1, 0]})";
  EXPECT_NE(sceneErrorOf(lights + R"(], "comment": nul})").find("$.lights: has 5000 elements (at most 4096)"),
            std::string::npos);
  std::string escaped = head + R"("obj\u0065cts": [)";
  const std::string object = R"({"generator": {"type": "box", "size": [1, 1, 1]}, "material": "m"})";
  for (int i = 0; i < 70000; ++i) escaped += (i ? ", " : "") + object;
  EXPECT_NE(sceneErrorOf(escaped + R"(], "comment": nul})").find("$.objects: has 70000 elements (at most 65536)"),
            std::string::npos);
  std::string values = head + R"("comment": [)";
  for (int i = 0; i < 4'100'000; ++i) values += i ? ",{}" : "{}";
  const std::string error = sceneErrorOf(values + "], nul}");
  EXPECT_NE(error.find("test.json: (document): holds more than 4000000 values"), std::string::npos)
      << error.substr(0, 200);
}

TEST(Scene, ACameraPathFileIsBoundedAsTheSceneIs) {
  // A 60 MB path file of nested arrays took 2.53 GB and 11-23 s before its error: the same scan now.
  const auto dir = std::filesystem::temp_directory_path() / "retroaa_bounded_path";
  std::filesystem::create_directories(dir);
  {
    std::ofstream path(dir / "path.json");
    path << R"({"keys": [)";
    for (int i = 0; i < 4'100'000; ++i) path << (i ? ",[]" : "[]");
    path << "]}";
  }
  std::string error;
  try {
    host::parseScene(
        R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "objects": [], "camera_path": "path.json"})",
        "scene.json", dir.string());
  } catch (const host::SceneError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("path.json: (document): holds more than 4000000 values"), std::string::npos) << error;
  EXPECT_NE(error.find("camera_path"), std::string::npos) << error;
  std::filesystem::remove_all(dir);
}

TEST(Scene, GeneratedMeshesAreCountedAgainstTheMemoryBudgetBeforeAnyIsBuilt) {
  // Eight greebled hulls of 200 000 greebles (19.2 M triangles, under the old 20 M cap) took 28 s and
  // 4.5 GB: their bytes are known from the file, so the scene is refused before the first is generated.
  std::string hulls;
  for (int i = 0; i < 8; ++i)
    hulls += std::string(i ? "," : "") +
             R"({"generator": {"type": "greebled_hull", "size": [10, 3, 20], "greebles": 200000}, "material": "m"})";
  const std::string error = sceneErrorOf(withObjects(hulls));
  EXPECT_NE(error.find("$.objects: the scene's meshes would take 1977 MiB"), std::string::npos) << error;
  EXPECT_NE(error.find("more than the 512 MiB budget"), std::string::npos) << error;
  // One hull of 50 000 greebles is 61.8 MiB, within the budget; repeated ten times it is not.
  const std::string oneHull =
      R"({"generator": {"type": "greebled_hull", "size": [10, 3, 20], "greebles": 50000}, "material": "m")";
  EXPECT_EQ(sceneErrorOf(withObjects(oneHull + "}")), "");
  EXPECT_NE(sceneErrorOf(withObjects(oneHull + R"(, "repeat": {"count": 10, "offset": [30, 0, 0]}})"))
                .find("$.objects: the scene's meshes would take 617 MiB"),
            std::string::npos);
  // A sphere's mesh (2.5 MiB at 32 subdivisions) repeated 10 000 times is counted as its copies are made.
  EXPECT_NE(sceneErrorOf(withObjects(
                             R"({"generator": {"type": "sphere", "radius": 1, "subdivisions": 32}, "material": "m",
                    "repeat": {"count": 10000, "offset": [3, 0, 0]}})"))
                .find("$.objects[0]: the scene's meshes would take"),
            std::string::npos);
}

TEST(Scene, AModelLargerThanAModelMayBeIsRefusedBeforeItIsRead) {
  // assimp reads a model whole before any of it can be counted: its file, and a .gltf's buffer files,
  // are bounded first. Sparse files: nothing of them is written.
  const auto dir = std::filesystem::temp_directory_path() / "retroaa_large_model";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "huge.obj") << "v 0 0 0\n";
  std::filesystem::resize_file(dir / "huge.obj", std::uintmax_t(65) << 20);
  std::ofstream(dir / "small.gltf")
      << R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "geometry.bin", "byteLength": 12}]})";
  std::ofstream(dir / "geometry.bin") << "x";
  std::filesystem::resize_file(dir / "geometry.bin", std::uintmax_t(70) << 20);
  auto errorFor = [&](const std::string& model) {
    try {
      host::parseScene(R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0]}, "materials": [{"name": "m"}],
                           "objects": [{"model": ")" +
                           model + R"(", "material": "m"}]})",
                       "scene.json", dir.string());
    } catch (const host::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string obj = errorFor("huge.obj");
  EXPECT_NE(obj.find("$.objects[0].model: '"), std::string::npos) << obj;
  EXPECT_NE(obj.find("huge.obj' is 65 MiB with the buffers it names, more than the 64 MiB a model may be"),
            std::string::npos)
      << obj;
  const std::string gltf = errorFor("small.gltf");
  EXPECT_NE(gltf.find("small.gltf' is 70 MiB with the buffers it names"), std::string::npos) << gltf;
  std::filesystem::remove_all(dir);
}

TEST(BoundedJson, EveryJsonFileTheToolsReadIsBoundedAndNamed) {
  // Goldens, tune's cache and capture records go through the scene's scan too.
  std::string deep(40, '[');
  deep += std::string(40, ']');
  try {
    host::parseBoundedJson(deep, "golden/ci/demo.json");
    ADD_FAILURE() << "40 levels of nesting were parsed";
  } catch (const host::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("golden/ci/demo.json: (document): nested more than 32 levels deep"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(host::parseBoundedJson(R"({"a": [1, 2]})", "x.json")["a"][1], 2);
  try {
    host::parseBoundedJson(R"({"a": })", "capture.jsonl:3");
    ADD_FAILURE() << "a syntax error was parsed";
  } catch (const host::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("capture.jsonl:3: (document): not valid JSON"), std::string::npos);
  }
}

TEST(Model, TexturesNamedWithBackslashesAreFoundAndAMissingOneIsNamed) {
  // OBJ and COLLADA files written on Windows name their textures ".\tex.png", "..\dir\tex.png".
  const auto dir = std::filesystem::temp_directory_path() / "retroaa_backslash_model";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "maps");
  std::vector<uint8_t> texels(4 * 4 * 4, 200);
  app::writeImage8((dir / "maps" / "tex.png").string(), 4, 4, texels);
  auto writeModel = [&](const std::string& textureName) {
    std::ofstream(dir / "m.mtl") << "newmtl painted\nKd 1 1 1\nmap_Kd " << textureName << "\n";
    std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                                    "usemtl painted\nf 1/1/1 2/2/1 3/3/1\n";
  };
  writeModel(".\\maps\\tex.png");
  const std::vector<host::ModelPart> parts = host::loadModel((dir / "m.obj").string());
  ASSERT_FALSE(parts.empty());
  bool textured = false;
  for (const host::ModelPart& part : parts) textured = textured || part.maps.albedo != nullptr;
  EXPECT_TRUE(textured) << "the backslash path reached the texture";
  writeModel(".\\maps\\missing.png");
  try {
    host::loadModel((dir / "m.obj").string());
    ADD_FAILURE() << "no error for a missing texture";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png: texture does not exist"), std::string::npos) << e.what();
  }
  // A scene that overrides the model's material reads none of its textures, so the missing one is no
  // error; and a scene whose objects all keep their own materials needs no "materials" key.
  const std::string model = (dir / "m.obj").string();
  const host::Scene overridden =
      host::parseScene(R"({"camera": "fit", "materials": [{"name": "plain"}], "objects": [{"model": ")" + model +
                           R"(", "material": "plain"}]})",
                       "override.json", dir.string());
  ASSERT_EQ(overridden.objects.size(), 1u);
  EXPECT_EQ(overridden.materials[size_t(overridden.objects[0].material)].name, "plain");
  writeModel(".\\maps\\tex.png");
  const host::Scene ownMaterials =
      host::parseScene(R"({"camera": "fit", "objects": [{"model": ")" + model + R"("}]})", "own.json", dir.string());
  ASSERT_EQ(ownMaterials.objects.size(), 1u);
  EXPECT_TRUE(ownMaterials.materials[size_t(ownMaterials.objects[0].material)].maps.albedo != nullptr);
}
