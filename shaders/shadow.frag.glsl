/* Shadow pass: the depth the vertex stage gave; the depth test keeps the nearest surface. */
void main()
{
  out_depth = light_depth;
}
