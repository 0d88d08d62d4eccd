#endif /* EL_EDGE_FLOOR (edge_floor.frag.glsl) */
