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
