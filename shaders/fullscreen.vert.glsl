/* A triangle covering the viewport (pos in [-1, 3]). */
void main()
{
  uv = pos * 0.5 + 0.5;
  gl_Position = vec4(pos, 0.0, 1.0);
}
