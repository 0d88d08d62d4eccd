/* Per-frame data shared by every pass (std140: vec4-sized members only). */
#define EL_MAX_LIGHTS 16
struct FrameData {
  mat4 view;                           /* world -> view */
  mat4 projection;                     /* view -> clip, sub-pixel jitter included */
  vec4 eye;                            /* world eye; w = 1 perspective, 0 orthographic */
  vec4 view_dir;                       /* world direction the camera looks along */
  vec4 viewport;                       /* width, height, 1/width, 1/height in pixels */
  vec4 ambient;                        /* world colour, scene-linear */
  vec4 camera;                         /* x: pixels per unit at distance 1 (perspective) or
                                          per unit (orthographic); y: light count */
  vec4 light_color[EL_MAX_LIGHTS];     /* rgb: colour x strength; w: 0 sun 1 point 2 spot 3 area */
  vec4 light_position[EL_MAX_LIGHTS];  /* xyz world */
  vec4 light_direction[EL_MAX_LIGHTS]; /* xyz: where the light points; w: cos(spot size / 2) */
  vec4 light_spot[EL_MAX_LIGHTS];      /* x: spot blend */
};
