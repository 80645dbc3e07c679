#pragma once
namespace effects::gl {

// Core profile draws need a vertex array bound even when the vertex shader makes its
// own vertices (full-screen triangles): binds one shared empty VAO, made on first use
// in the current context.
void bind_empty_vertex_array();

}  // namespace effects::gl
