// The G-buffer attachments, in FreeSpace Open's order.
layout(location = 0) out vec4 outColor;     // albedo rgb, 1
layout(location = 1) out vec4 outPosition;  // view x/d, y/d, encodeDepth(d), 1 (0 for background)
layout(location = 2) out vec4 outNormal;    // view-space normal, gloss
layout(location = 3) out vec4 outSpecular;  // specular colour (RGBA8)
layout(location = 4) out vec4 outEmissive;  // emissive radiance; the sky for background pixels
layout(location = 5) out vec4 outVelocity;  // screen motion in pixels, this − previous frame (where allocated)
