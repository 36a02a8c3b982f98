//! The SPIR-V reader against the committed shaders and hand-made modules.

use super::*;

fn words(bytes: &[u8]) -> Vec<u32> {
    spirv_words(bytes).expect("SPIR-V")
}

#[test]
fn a_vertex_shader_reads_its_input_locations() {
    let triangle = interface(&words(include_bytes!(
        "../../../shaders/spv/triangle.vert.spv"
    )));
    assert_eq!(
        triangle.vertex_inputs,
        [("main".to_owned(), vec![(0, 1), (1, 1)])]
    );
    assert!(triangle.reads_vertex_location(b"main", 1));
    assert_eq!(triangle.entry_points.len(), 1);
    assert_eq!(
        (
            triangle.entry_points[0].name.as_str(),
            triangle.entry_points[0].model
        ),
        ("main", 0)
    );
    let entry = |name: &[u8], stage| triangle.entry_point(name, stage).is_some();
    assert!(entry(b"main", ash::vk::ShaderStageFlags::VERTEX));
    assert!(!entry(b"main", ash::vk::ShaderStageFlags::FRAGMENT));
    assert!(!entry(b"other", ash::vk::ShaderStageFlags::VERTEX));
    assert!(!triangle.reads_vertex_location(b"main", 2));
    assert!(!triangle.reads_vertex_location(b"other", 0));
    let test = interface(&words(include_bytes!("../../../shaders/spv/test.vert.spv")));
    assert_eq!(test.vertex_inputs, [("main".to_owned(), vec![])]);
}

#[test]
fn the_test_shaders_interfaces() {
    let comp = interface(&words(include_bytes!("../../../shaders/spv/test.comp.spv")));
    let mut found: Vec<(u32, u32, ResourceKind, u32)> = comp
        .resources
        .iter()
        .map(|r| (r.set, r.binding, r.kind, r.count))
        .collect();
    found.sort_unstable_by_key(|r| (r.0, r.1));
    assert_eq!(
        found,
        [
            (0, 0, ResourceKind::UniformBuffer, 1),
            (0, 1, ResourceKind::StorageBuffer, 1)
        ]
    );
    assert_eq!(comp.push_constants, None);
    assert!(comp.resources.iter().all(|r| r.image.is_none()));
    let image = interface(&words(include_bytes!(
        "../../../shaders/spv/image.comp.spv"
    )));
    let shape = image
        .resources
        .iter()
        .find(|r| r.binding == 0)
        .and_then(|r| r.image)
        .expect("the storage image");
    assert_eq!(
        shape,
        ImageShape {
            dim: 1,
            arrayed: false,
            numeric: 1,
            // rgba8
            format: 4,
        }
    );
    assert_eq!(shape.view_type(), Some(ash::vk::ImageViewType::TYPE_2D));
    let ops_of = |bytes: &[u8], binding: u32| {
        interface(&words(bytes))
            .resources
            .iter()
            .find(|r| r.binding == binding)
            .map(|r| r.ops)
    };
    // imageLoad reads the storage image.
    assert_eq!(
        ops_of(include_bytes!("../../../shaders/spv/image.comp.spv"), 0),
        Some(ops::READ | ops::NOT_SAMPLE)
    );
    // The output block is a buffer the shader stores to.
    assert_eq!(
        ops_of(include_bytes!("../../../shaders/spv/image.comp.spv"), 1),
        Some(ops::STORE)
    );
    assert_eq!(
        ops_of(include_bytes!("../../../shaders/spv/atomic.comp.spv"), 0),
        Some(ops::ATOMIC | ops::NOT_SAMPLE)
    );
    // texture() samples with an implicit LOD; textureLodOffset with an offset.
    assert_eq!(
        ops_of(
            include_bytes!("../../../shaders/spv/sample_uint.frag.spv"),
            0
        ),
        Some(ops::SAMPLE | ops::IMPLICIT_DREF_PROJ)
    );
    assert_eq!(
        ops_of(
            include_bytes!("../../../shaders/spv/sample_lod.frag.spv"),
            0
        ),
        Some(ops::SAMPLE | ops::SAMPLE_BIAS_OFFSET | ops::OFFSET)
    );
    // imageStore writes four components.
    let store = interface(&words(include_bytes!(
        "../../../shaders/spv/image_store.frag.spv"
    )));
    assert_eq!(store.resources[0].write_components, 4);
    assert_eq!(store.resources[0].ops, ops::WRITE | ops::NOT_SAMPLE);
    let frag = interface(&words(include_bytes!("../../../shaders/spv/test.frag.spv")));
    assert!(frag.resources.is_empty());
    // The test fragment shader pushes one vec4.
    assert_eq!(frag.push_constants, Some((0, 16)));
}

#[test]
fn entry_points_keep_their_execution_modes() {
    let geometry = interface(&words(include_bytes!(
        "../../../shaders/spv/points.geom.spv"
    )));
    let e = geometry
        .entry_point(b"main", ash::vk::ShaderStageFlags::GEOMETRY)
        .expect("the geometry entry point");
    // InputPoints, OutputPoints, OutputVertices 1, Invocations 1.
    assert!(e.mode(19).is_some());
    assert!(e.mode(27).is_some());
    assert_eq!(e.mode(26), Some(&[1][..]));
    assert_eq!(e.mode(0), Some(&[1][..]));
    let tese = interface(&words(include_bytes!(
        "../../../shaders/spv/bezier.tese.spv"
    )));
    let e = tese
        .entry_point(b"main", ash::vk::ShaderStageFlags::TESSELLATION_EVALUATION)
        .expect("the evaluation entry point");
    // Quads.
    assert_eq!(e.first_of(&[22, 24, 25]), Some(24));
    // The geometry shader reads gl_in[] and writes gl_PerVertex: Position (0) and
    // PointSize (1) among the members of each block (Input 1, Output 3).
    let builtins = &interface(&words(include_bytes!(
        "../../../shaders/spv/points.geom.spv"
    )))
    .entry_points[0]
        .builtins;
    assert!(builtins.contains(&(0, 1, 1)));
    assert!(builtins.contains(&(1, 3, 1)));
    // It writes Position and PointSize; the test vertex shader Position only.
    let geometry = interface(&words(include_bytes!(
        "../../../shaders/spv/points.geom.spv"
    )));
    assert_eq!(geometry.entry_points[0].writes, [0, 1]);
    let vertex = interface(&words(include_bytes!("../../../shaders/spv/test.vert.spv")));
    assert_eq!(vertex.entry_points[0].writes, [0]);
}

#[test]
fn interface_variables_keep_their_locations_and_types() {
    use super::{IoType, IoVar};
    let vec = |n| IoType::Vector(Box::new(IoType::Scalar(0, 32)), n);
    let var = |output, location, ty| IoVar {
        output,
        location,
        component: 0,
        patch: false,
        ty,
    };
    // The geometry stage's per-vertex input array is taken off.
    let geom = interface(&words(include_bytes!(
        "../../../shaders/spv/varying.geom.spv"
    )));
    let mut io = geom.entry_points[0].io.clone();
    io.sort_unstable_by_key(|v| v.output);
    assert_eq!(io, [var(false, 0, vec(4)), var(true, 0, vec(4))]);
    let full = vec![(0, 1), (1, 1), (3, 1), (4, 1)];
    assert_eq!(
        geom.entry_points[0].builtin_blocks,
        [full.clone(), full.clone()]
    );
    let frag = interface(&words(include_bytes!(
        "../../../shaders/spv/bezier.frag.spv"
    )));
    let inputs: Vec<_> = frag.entry_points[0]
        .io
        .iter()
        .filter(|v| !v.output)
        .cloned()
        .collect();
    assert_eq!(inputs, [var(false, 0, vec(3)), var(false, 1, vec(3))]);
    // A redeclared output block of gl_Position alone.
    let vert = interface(&words(include_bytes!(
        "../../../shaders/spv/position_only.vert.spv"
    )));
    assert_eq!(vert.entry_points[0].builtin_blocks, [vec![], vec![(0, 1)]]);
    // A vector of more components matches a narrower input only with narrowing.
    assert!(vec(4).matches(&vec(4), false));
    assert!(!vec(4).matches(&vec(3), false));
    assert!(vec(4).matches(&vec(3), true));
    assert!(!vec(3).matches(&vec(4), true));
    assert!(!IoType::Unknown.matches(&IoType::Unknown, true));
    assert!(!IoType::Array(Box::new(vec(4)), 0).matches(&IoType::Array(Box::new(vec(4)), 0), false));
}

#[test]
fn specialization_constants_keep_their_sizes() {
    let spec = interface(&words(include_bytes!("../../../shaders/spv/spec.vert.spv")));
    assert_eq!(spec.spec_constants, [(0, 4)]);
    let test = interface(&words(include_bytes!("../../../shaders/spv/test.vert.spv")));
    assert!(test.spec_constants.is_empty());
}

#[test]
fn a_truncated_module_keeps_what_was_read() {
    let mut w = words(include_bytes!("../../../shaders/spv/test.comp.spv"));
    w.truncate(20);
    let _ = interface(&w);
    assert_eq!(interface(&w[..3]), Interface::default());
}

/// A structure made of sixteen copies of itself (malformed: SPIR-V types cannot
/// contain themselves) would be 16^16 types to walk; the walk stops at its budget.
#[test]
fn a_self_containing_structure_is_walked_within_the_budget() {
    let mut w = vec![MAGIC, 0x0001_0000, 0, 16, 0];
    let op = |count: u32, code: u32| (count << 16) | code;
    w.extend([op(3, 22), 1, 32]); // %1 = OpTypeFloat 32
    w.push(op(18, 30)); // %2 = OpTypeStruct %2 x 16
    w.push(2);
    w.extend([2; 16]);
    w.extend([op(4, 32), 3, 3, 2]); // %3 = OpTypePointer Output %2
    w.extend([op(4, 59), 3, 4, 3]); // %4 = OpVariable %3 Output
    w.extend([op(5, 15), 0, 5, u32::from_le_bytes(*b"m\0\0\0"), 4]);
    w.extend([op(4, 71), 4, 30, 0]); // OpDecorate %4 Location 0
    let reflected = interface(&w);
    let entry = &reflected.entry_points[0];
    assert_eq!(entry.io.len(), 1, "{entry:?}");
    let _ = (
        entry.io[0].ty.locations(),
        entry.io[0].ty.matches(&entry.io[0].ty, true),
    );
}
