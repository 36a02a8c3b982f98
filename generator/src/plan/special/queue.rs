//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/queue.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Queue submissions: batches of command buffers, semaphores and fences checked
//! before they reach the queue, and the bookkeeping after (pending state, timelines,
//! queue families).

use super::{call, How, Special, BINARY_STATE, CHAINED_COUNT, FENCE, NONE, ONE_WAITER, UNPROVEN};

const CBS: &str = "checks each command buffer's lifecycle state, kept by the wrapper from its allocation, begin, end and submissions";
const SECONDARY: &str = "checked by the safe methods in every build (a secondary without SIMULTANEOUS_USE that is pending is refused), but no test breaks it yet: recording a pending secondary into another primary is refused (VUID-vkCmdExecuteCommands-pCommandBuffers-00091), so only a second submission of a SIMULTANEOUS_USE primary that executes it reaches the state, and the layer warns at that execution already";
const UNPROVEN_POOL_FAMILY: &str = "checked by the safe methods in every build (the pool's queue family, recorded at its creation and read at each begin, against the queue's), but no test breaks it: lavapipe has one queue family";
const UNPROVEN_PROTECTED_BUFFERS: &str = "checked by the safe methods in every build (the pool's protected flag, recorded at its creation, against the batch's VkProtectedSubmitInfo), but no test breaks it: lavapipe has no protectedMemory, so no pool is protected, and a protected batch is refused for its queue first";
const UNPROVEN_OTHER_QUEUE_EVENTS: &str = "checked by the safe methods in every build (the events each recording's set, reset and wait commands name, against those of the submissions to other queues not known complete), but no test breaks it: lavapipe's queue family has one queue";
const UNPROVEN_TIMELINE_DIFFERENCE: &str = "checked by the safe methods in every build (against the semaphore's possible values, from the value the host last saw to the largest signalled, and the values of its pending operations), but no test breaks it: lavapipe's maxTimelineSemaphoreValueDifference is the largest 64-bit value";
const TIMELINE_RISES: &str = "checks each timeline signal is above the largest value the semaphore was given (initial value, host signals, submitted signals, earlier batches of the call): a bound stricter than the rule's, as the order in which queues execute is not known";
const PROTECTED_QUEUE: &str = "checks a protected batch's queue was got with VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT, which the device records";
const TIMELINE_VALUES: &str =
    "checks each batch gives one value per timeline semaphore it waits on or signals";
const QUEUE_INFOS: &str =
    "checks the family, flags and index against the queue create infos the device recorded at its creation";
const BINARY_SIGNALED: &str = "checks the binary semaphore's state, as for a wait: a signal needs it unsignaled, or waited on earlier on the same queue (the 1.3.239 layer reports the rule as UNASSIGNED-CoreValidation-DrawState-QueueForwardProgress, \"signaled ... but has not since been waited on\")";
const SAME_AS_03238: &str = "checked by the safe methods in every build, by the check of VUID-vkQueueSubmit-pWaitSemaphores-03238, whose condition it shares for binary semaphores and whose VUID the error names (a timeline semaphore may be waited on before its signal is submitted, as the timeline rules allow)";
const UNPROVEN_BINARY: &str = "checked by the safe methods in every build (the binary semaphore's state, as for vkQueueSubmit), but no test breaks it through this command";
const WAIT_STAGES: &str = "checks each wait stage mask: no host stage, no geometry or tessellation stage without its feature, not 0 without synchronization2, and each stage one the queue's capabilities (its family's flags, recorded when it was got) support";
const UNPROVEN_QUEUE_STAGES: &str = "checked by the safe methods in every build (each stage against the queue family's flags and the specification's table of supported stages), but no test breaks it: lavapipe's only queue family supports every stage";
const GROUP_INDICES: &str = "checks a chained device group info's device indices and masks against the device's physical-device count, recorded at its creation";

const UNPROVEN_GROUP_INDEX: &str = "checked by the safe methods in every build (the device's physical device count, recorded at its creation), but no test breaks it: lavapipe's devices are not device groups";
const DEVICE_INDEX_ALONE: &str = "checks a semaphore's device index against the device's physical-device count, recorded at its creation (the 1.3.239 layer does not check it: proven by the error alone)";
const DEVICE_MASK: &str = "checks a command buffer's device mask against the device's physical-device count, recorded at its creation";
const WAIT_BELOW_SIGNAL: &str = "checks, for each timeline semaphore a batch both waits on and signals, that the wait's value is below the signal's";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkQueueSubmit",
        check: call(
            "special::queue::queue_submit_checks",
            &["self", "submits", "fence"],
        ),
        hold: call("special::queue::queue_submit_hold", &["self", "submits"]),
        after: call(
            "special::queue::queue_submit_done",
            &["self", "submits", "fence"],
        ),
        settles: &[
            ("VUID-vkQueueSubmit-fence-00063", How::Dynamic(FENCE)),
            ("VUID-vkQueueSubmit-fence-00064", How::Dynamic(FENCE)),
            ("VUID-VkSubmitInfo-pCommandBuffers-00075", How::Dynamic(CBS)),
            (
                "VUID-vkQueueSubmit-pCommandBuffers-00070",
                How::Dynamic(CBS),
            ),
            (
                "VUID-vkQueueSubmit-pCommandBuffers-00071",
                How::Dynamic(CBS),
            ),
            (
                "VUID-vkQueueSubmit-pCommandBuffers-00072",
                How::Dynamic(CBS),
            ),
            (
                "VUID-vkQueueSubmit-pCommandBuffers-00073",
                How::User(SECONDARY),
            ),
            (
                "VUID-VkSubmitInfo-pWaitSemaphores-03239",
                How::Dynamic(TIMELINE_VALUES),
            ),
            (
                "VUID-VkSubmitInfo-pNext-03240",
                How::Dynamic(TIMELINE_VALUES),
            ),
            (
                "VUID-VkSubmitInfo-pNext-03241",
                How::Dynamic(TIMELINE_VALUES),
            ),
            (
                "VUID-VkDeviceGroupSubmitInfo-waitSemaphoreCount-00082",
                How::Dynamic(CHAINED_COUNT),
            ),
            (
                "VUID-VkDeviceGroupSubmitInfo-commandBufferCount-00083",
                How::Dynamic(CHAINED_COUNT),
            ),
            (
                "VUID-VkDeviceGroupSubmitInfo-signalSemaphoreCount-00084",
                How::Dynamic(CHAINED_COUNT),
            ),
            (
                "VUID-vkQueueSubmit-pWaitSemaphores-03238",
                How::Dynamic(BINARY_STATE),
            ),
            (
                "VUID-VkSubmitInfo-pWaitDstStageMask-00078",
                How::Dynamic(WAIT_STAGES),
            ),
            (
                "VUID-VkSubmitInfo-pWaitDstStageMask-04090",
                How::Dynamic(WAIT_STAGES),
            ),
            (
                "VUID-VkSubmitInfo-pWaitDstStageMask-04091",
                How::Dynamic(WAIT_STAGES),
            ),
            (
                "VUID-VkSubmitInfo-pWaitDstStageMask-03937",
                How::Dynamic(WAIT_STAGES),
            ),
            (
                "VUID-vkQueueSubmit-pWaitDstStageMask-00066",
                How::User(UNPROVEN_QUEUE_STAGES),
            ),
            (
                "VUID-VkDeviceGroupSubmitInfo-pWaitSemaphoreDeviceIndices-00085",
                How::Dynamic(GROUP_INDICES),
            ),
            (
                "VUID-VkDeviceGroupSubmitInfo-pCommandBufferDeviceMasks-00086",
                How::Dynamic(GROUP_INDICES),
            ),
            (
                "VUID-vkQueueSubmit-pSignalSemaphores-00067",
                How::Dynamic(BINARY_SIGNALED),
            ),
            (
                "VUID-vkQueueSubmit-pWaitSemaphores-00069",
                How::User(SAME_AS_03238),
            ),
            (
                "VUID-vkQueueSubmit-pWaitSemaphores-00068",
                How::User(ONE_WAITER),
            ),
            (
                "VUID-vkQueueSubmit-pCommandBuffers-00074",
                How::User(UNPROVEN_POOL_FAMILY),
            ),
            (
                "VUID-vkQueueSubmit-queue-06448",
                How::Dynamic(PROTECTED_QUEUE),
            ),
            (
                "VUID-VkSubmitInfo-pNext-04120",
                How::User(UNPROVEN_PROTECTED_BUFFERS),
            ),
            (
                "VUID-VkSubmitInfo-pNext-04148",
                How::User(UNPROVEN_PROTECTED_BUFFERS),
            ),
            (
                "VUID-vkQueueSubmit-pCommandBuffers-00065",
                How::User(UNPROVEN_OTHER_QUEUE_EVENTS),
            ),
            (
                "VUID-VkSubmitInfo-pSignalSemaphores-03242",
                How::Dynamic(TIMELINE_RISES),
            ),
            (
                "VUID-VkSubmitInfo-pWaitSemaphores-03243",
                How::User(UNPROVEN_TIMELINE_DIFFERENCE),
            ),
            (
                "VUID-VkSubmitInfo-pSignalSemaphores-03244",
                How::User(UNPROVEN_TIMELINE_DIFFERENCE),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkQueueSubmit2",
        check: call(
            "special::queue::queue_submit2_checks",
            &["self", "submits", "fence"],
        ),
        hold: call("special::queue::queue_submit2_hold", &["self", "submits"]),
        after: call(
            "special::queue::queue_submit2_done",
            &["self", "submits", "fence"],
        ),
        settles: &[
            ("VUID-vkQueueSubmit2-fence-04894", How::Dynamic(FENCE)),
            ("VUID-vkQueueSubmit2-fence-04895", How::Dynamic(FENCE)),
            (
                "VUID-VkCommandBufferSubmitInfo-commandBuffer-03890",
                How::Dynamic(CBS),
            ),
            ("VUID-vkQueueSubmit2-commandBuffer-03874", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit2-commandBuffer-03875", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit2-commandBuffer-03876", How::Dynamic(CBS)),
            (
                "VUID-vkQueueSubmit2-commandBuffer-03877",
                How::User(SECONDARY),
            ),
            (
                "VUID-vkQueueSubmit2-semaphore-03873",
                How::User(UNPROVEN_BINARY),
            ),
            (
                "VUID-vkQueueSubmit2-semaphore-03868",
                How::User(UNPROVEN_BINARY),
            ),
            (
                "VUID-vkQueueSubmit2-semaphore-03872",
                How::User(UNPROVEN_BINARY),
            ),
            ("VUID-vkQueueSubmit2-semaphore-03871", How::User(ONE_WAITER)),
            (
                "VUID-vkQueueSubmit2-commandBuffer-03867",
                How::User(UNPROVEN_OTHER_QUEUE_EVENTS),
            ),
            (
                "VUID-vkQueueSubmit2-stageMask-03869",
                How::User(UNPROVEN_QUEUE_STAGES),
            ),
            (
                "VUID-vkQueueSubmit2-stageMask-03870",
                How::User(UNPROVEN_QUEUE_STAGES),
            ),
            (
                "VUID-vkQueueSubmit2-commandBuffer-03878",
                How::User(UNPROVEN_POOL_FAMILY),
            ),
            (
                "VUID-vkQueueSubmit2-queue-06447",
                How::Dynamic(PROTECTED_QUEUE),
            ),
            (
                "VUID-VkSubmitInfo2-flags-03886",
                How::User(UNPROVEN_PROTECTED_BUFFERS),
            ),
            (
                "VUID-VkSubmitInfo2-flags-03887",
                How::User(UNPROVEN_PROTECTED_BUFFERS),
            ),
            (
                "VUID-VkCommandBufferSubmitInfo-deviceMask-03891",
                How::Dynamic(DEVICE_MASK),
            ),
            (
                "VUID-VkSemaphoreSubmitInfo-device-03888",
                How::Dynamic(DEVICE_INDEX_ALONE),
            ),
            (
                "VUID-VkSemaphoreSubmitInfo-device-03889",
                How::User(UNPROVEN_GROUP_INDEX),
            ),
            (
                "VUID-VkSubmitInfo2-semaphore-03881",
                How::Dynamic(WAIT_BELOW_SIGNAL),
            ),
            (
                "VUID-VkSubmitInfo2-semaphore-03882",
                How::Dynamic(TIMELINE_RISES),
            ),
            (
                "VUID-VkSubmitInfo2-semaphore-03883",
                How::User(UNPROVEN_TIMELINE_DIFFERENCE),
            ),
            (
                "VUID-VkSubmitInfo2-semaphore-03884",
                How::User(UNPROVEN_TIMELINE_DIFFERENCE),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkQueueBindSparse",
        check: call(
            "special::queue::queue_bind_sparse_checks",
            &["self", "bind_info", "fence"],
        ),
        hold: call(
            "special::queue::queue_bind_sparse_hold",
            &["self", "bind_info"],
        ),
        after: call(
            "special::queue::queue_bind_sparse_done",
            &["self", "bind_info", "fence"],
        ),
        required: &["fence"],
        settles: &[
            ("VUID-vkQueueBindSparse-fence-01113", How::Dynamic(FENCE)),
            ("VUID-vkQueueBindSparse-fence-01114", How::Dynamic(FENCE)),
            (
                "VUID-VkBindSparseInfo-pWaitSemaphores-03246",
                How::User(UNPROVEN),
            ),
            ("VUID-VkBindSparseInfo-pNext-03247", How::User(UNPROVEN)),
            ("VUID-VkBindSparseInfo-pNext-03248", How::User(UNPROVEN)),
            (
                "VUID-vkQueueBindSparse-pWaitSemaphores-03245",
                How::User(UNPROVEN_BINARY),
            ),
            (
                "VUID-vkQueueBindSparse-pWaitSemaphores-01117",
                How::User(UNPROVEN_BINARY),
            ),
            (
                "VUID-vkQueueBindSparse-pSignalSemaphores-01115",
                How::User(UNPROVEN_BINARY),
            ),
            (
                "VUID-vkQueueBindSparse-pWaitSemaphores-01116",
                How::User(ONE_WAITER),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkQueueWaitIdle",
        after: call("special::queue::queue_wait_idle_done", &["self"]),
        ..NONE
    },
    Special {
        command: "vkDeviceWaitIdle",
        after: call("special::queue::device_wait_idle_done", &["self"]),
        ..NONE
    },
    Special {
        command: "vkGetDeviceQueue",
        check: call(
            "special::queue::get_device_queue_checks",
            &["self", "queue_family_index", "queue_index"],
        ),
        created: call(
            "special::queue::queue_got",
            &["self", "created", "queue_family_index"],
        ),
        settles: &[
            (
                "VUID-vkGetDeviceQueue-queueFamilyIndex-00384",
                How::Dynamic(QUEUE_INFOS),
            ),
            (
                "VUID-vkGetDeviceQueue-queueIndex-00385",
                How::Dynamic(QUEUE_INFOS),
            ),
            (
                "VUID-vkGetDeviceQueue-flags-01841",
                How::Dynamic(QUEUE_INFOS),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetDeviceQueue2",
        check: call(
            "special::queue::get_device_queue2_checks",
            &["self", "queue_info"],
        ),
        created: call(
            "special::queue::queue2_got",
            &["self", "created", "queue_info"],
        ),
        settles: &[
            (
                "VUID-VkDeviceQueueInfo2-queueFamilyIndex-01842",
                How::Dynamic(QUEUE_INFOS),
            ),
            (
                "VUID-VkDeviceQueueInfo2-flags-06225",
                How::Dynamic(QUEUE_INFOS),
            ),
            (
                "VUID-VkDeviceQueueInfo2-queueIndex-01843",
                How::Dynamic(QUEUE_INFOS),
            ),
        ],
        ..NONE
    },
];
