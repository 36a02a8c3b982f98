//! The scenes, as libraries so that tests can render them; `src/bin` holds their
//! command lines.

pub mod bezier;
pub mod bezier_view;
pub mod deferred;
pub mod deferred_data;
pub mod teapot_grid;
pub mod teapots;
pub mod textured_quad;
pub mod triangle;
pub mod triangle_vertices;
