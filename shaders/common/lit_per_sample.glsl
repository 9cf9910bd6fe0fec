// For a post filter stacked on a method that lights samples through slices: the pixels that method lit
// sample by sample (SliceRenderer's counts, > 1) hold their samples' mix already; blending them again by
// their coverage mixes the neighbour in twice. The includer defines LIT_PER_SAMPLE_BINDING; the plugin
// prepends LIT_PER_SAMPLE (the base lights slices).
#if LIT_PER_SAMPLE
layout(binding = LIT_PER_SAMPLE_BINDING) uniform usampler2D uSliceCounts;
bool litPerSample(ivec2 pixel) { return texelFetch(uSliceCounts, pixel, 0).r > 1u; }
#else
bool litPerSample(ivec2 pixel) { return false; }
#endif
