// The forward mask (ForwardMask, shaders/forward/mark_drawn.frag) for the post filters that rebuild a pixel
// from its neighbours' colours: they know the opaque surfaces' depth alone. The includer defines
// FORWARD_MASK_BINDING; the plugin prepends FORWARD_MASK (the host draws forward passes).
#if FORWARD_MASK
layout(binding = FORWARD_MASK_BINDING) uniform sampler2D uForwardDrawn;  // 0 nothing, 0.5 a film, 1 an edge
float forwardMark(ivec2 pixel) {
  return texelFetch(uForwardDrawn, clamp(pixel, ivec2(0), textureSize(uForwardDrawn, 0) - 1), 0).r;
}
#else
float forwardMark(ivec2 pixel) { return 0.0; }
#endif

bool isForwardEdge(float mark) { return mark > 0.75; }
bool isForwardFilm(float mark) { return mark > 0.25 && mark < 0.75; }

// An edge of what the forward passes drew: the pixel keeps its colour and lends it to no neighbour.
bool forwardEdge(ivec2 pixel) { return isForwardEdge(forwardMark(pixel)); }

// Under a forward film (a faint particle's smoke): its neighbours under the same film may stand in.
bool underForwardFilm(ivec2 pixel) { return isForwardFilm(forwardMark(pixel)); }

// Whether neighbour q's colour may stand in for a surface of a pixel (`pixelUnderFilm`: the pixel's own
// underForwardFilm): no forward edge at q, and a film over both or over neither. One read of q's mark.
bool lendsColour(ivec2 q, bool pixelUnderFilm) {
  float mark = forwardMark(q);
  return !isForwardEdge(mark) && isForwardFilm(mark) == pixelUnderFilm;
}
