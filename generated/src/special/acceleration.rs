//! Acceleration structure builds: each build info's range arrays against its geometry count.

use crate::structs::*;
use crate::{Error, Result};

/// Each build info's array of per-geometry values (build ranges, maximum primitive
/// counts) holds at least its `geometryCount` elements, which Vulkan reads. `vuid`
/// names the rule where the specification has one.
pub(crate) fn per_geometry_fits<T>(
    infos: &[AccelerationStructureBuildGeometryInfoKHR<'_>],
    arrays: &[&[T]],
    vuid: Option<&'static str>,
) -> Result<()> {
    for (i, (info, array)) in infos.iter().zip(arrays).enumerate() {
        let needed = info.geometry_count as usize;
        if array.len() < needed {
            let message = format!(
                "element {i} holds {} values where its build info has {needed} geometries",
                array.len()
            );
            return Err(match vuid {
                Some(vuid) => Error::Validation { vuid, message },
                None => Error::Misuse(
                    "each build info's array of maximum primitive counts must hold a value per geometry",
                ),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::per_geometry_fits;
    use crate::*;

    fn vuid(r: crate::Result<()>) -> Option<&'static str> {
        match r {
            Err(Error::Validation { vuid, .. }) => Some(vuid),
            _ => None,
        }
    }

    // The build-range arrays a safe build takes are checked against each build
    // info's geometry count, which is what Vulkan reads from them.
    #[test]
    fn build_ranges_hold_a_range_per_geometry() {
        let geometry =
            AccelerationStructureGeometryKHR::new(AccelerationStructureGeometryDataKHR::Triangles(
                AccelerationStructureGeometryTrianglesDataKHR::default(),
            ));
        let geometries = [geometry, geometry];
        let infos = [AccelerationStructureBuildGeometryInfoKHR::default().geometries(&geometries)];
        let range = vk::AccelerationStructureBuildRangeInfoKHR::default();
        let vuid03676 = "VUID-vkCmdBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676";
        assert_eq!(
            vuid(per_geometry_fits(&infos, &[&[range][..]], Some(vuid03676))),
            Some(vuid03676)
        );
        assert!(per_geometry_fits(&infos, &[&[range, range][..]], Some(vuid03676)).is_ok());
        assert!(matches!(
            per_geometry_fits(&infos, &[&[7u32][..]], None),
            Err(Error::Misuse(_))
        ));
    }
}
