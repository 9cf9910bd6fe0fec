#version 450 core
// SMAA S2x lights two samples of every pixel: the slice count is 2 everywhere.
#if STENCIL_EXPORT
#extension GL_ARB_shader_stencil_export : require
#endif
layout(location = 0) out uint outCount;
void main() {
  outCount = 2u;
#if STENCIL_EXPORT
  gl_FragStencilRefARB = 2;
#endif
}
