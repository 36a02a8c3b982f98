//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/sync.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Fences, semaphores and events: their creation, host waits and signals, timeline
//! values, and events set, reset and waited on in recordings.

use super::{call, How, Special, NONE, SEMAPHORE_TYPE, UNPROVEN_FAMILY};

const EVENT_STAGES: &str =
    "checks the stage mask is not 0 where the device does not enable synchronization2";
const HOST_SIGNAL: &str = "checks, under the device's submission gate held until the call's bookkeeping is done, the value against the semaphore's value read from the driver and the submitted operations the device records; a host signal while a submitted signal of the semaphore may be pending is refused (Error::Misuse), as the device could pass the host's value before the call";
const UNPROVEN_HOST_DIFFERENCE: &str = "checked by the safe methods in every build (against the value read from the driver and the pending operations the device records), but no test breaks it: lavapipe's maxTimelineSemaphoreValueDifference is the largest value a u64 holds";
const DEVICE_MASK: &str = "checks that the mask names no physical device past the device's count (the device records how many it was created with)";
const UNPROVEN_INITIAL_MASK: &str = "checked by the safe methods in every build (against the initial device mask the recorder keeps from the command buffer's begin, and the mask a chained VkDeviceGroupRenderPassBeginInfo gave the render pass instance), but no test breaks it: lavapipe's devices have one physical device, whose only valid mask is every device's";
const SET_EVENT2_FLAGS: &str = "checks the dependency info's flags are 0";
const HOST_RESET_PENDING: &str = "checks, under the device's submission gate held through the reset, that no submission whose command buffers name the event (the events each recording's set, reset and wait commands name, recorded per submission) may still be executing, asking their fences: a stricter bound than the rule's, which a wait alone needs (the 1.3.239 layer does not check it: the error alone proves it)";
const HOST_RESET_SAME: &str = "checked by the safe methods in every build, by the check of VUID-vkResetEvent-event-03821, whose condition (a pending submission names the event) includes this one and whose VUID the error names";
const UNPROVEN_ONE_DEVICE: &str = "checked by the safe methods in every build (the command buffer's current device mask, which the recorder follows from its begin and every vkCmdSetDeviceMask), but no test breaks it: lavapipe's devices have one physical device";
const DEVICE_ONLY: &str =
    "checks the event was not created device-only, which the device records at its creation";
const WAIT_SIGNALS: &str = "checks each event's state as the wait will see it: the recording follows what its own sets and resets leave (the stage mask of vkCmdSetEvent, the dependency info of vkCmdSetEvent2, unsignaled), and each submission checks the waits on events the command buffer did not set or reset against what the submissions before it and the host's vkSetEvent and vkResetEvent left, in submission order, under the device's submission gate; an event the host set while a submission that sets or resets it may still run is refused as not known";
const WAIT_HOST_BEFORE: &str = "checks, as for the other rules of the events' states, that an event whose wait holds only host operations is set by the host before the submission (a set after it, before the wait executes, is refused: tuff cannot see when the wait executes; the 1.3.239 layer does not check it: the error alone proves it)";
const WAIT_SCOPES: &str = "checks the wait's stages and each barrier's access types as a pipeline barrier's (the specification's table of the stages each access type is supported by)";
const WAIT_HOST_IN_PASS: &str =
    "checks the source stages against the render pass instance the recorder is inside";
const WAIT_FAMILIES: &str =
    "checks each buffer and image barrier names one queue family on both sides";
const RESET_RACE: &str = "checks that a pipeline barrier recorded between a wait on the event and the reset orders the reset's stages after the wait's (its srcStageMask holds the wait's dstStageMask, or all commands, and its dstStageMask the reset's stage), and, for a reset no barrier from all commands precedes in its command buffer, at each submission, under the device's submission gate, that no wait on the event in an earlier command buffer of the submission or a submission that may still be executing comes before it (the 1.3.239 layer's synchronization validation reports it as SYNC-vkCmdResetEvent-missingbarrier-wait)";
const WAIT_SIGNALS_ALONE: &str = "checks each event's state as for the wait's other rules of its events' signals (the 1.3.239 layer does not check it: the error alone proves it)";
const EXPORTABLE: &str = "checks each handle type is exportable and the set compatible, as the physical device's external properties report (the 1.3.239 layer does not check it: proven by the error alone)";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkResetFences",
        check: call("special::sync::reset_fences_checks", &["self", "fences"]),
        settles: &[(
            "VUID-vkResetFences-pFences-01123",
            How::Dynamic("refuses a fence whose queue operation may still be executing (asks the fence when the wrappers have not seen it signalled)"),
        )],
        ..NONE
    },
    Special {
        command: "vkGetSemaphoreCounterValue",
        check: call("special::sync::get_semaphore_counter_value_checks", &["self", "semaphore"]),
        after: call("special::sync::semaphore_value_seen", &["self", "semaphore", "out"]),
        settles: &[(
            "VUID-vkGetSemaphoreCounterValue-semaphore-03255",
            How::Dynamic(SEMAPHORE_TYPE),
        )],
        ..NONE
    },
    Special {
        command: "vkWaitSemaphores",
        check: call("special::sync::wait_semaphores_checks", &["self", "wait_info"]),
        after: call("special::sync::wait_semaphores_done", &["self", "wait_info", "r"]),
        settles: &[(
            "VUID-VkSemaphoreWaitInfo-pSemaphores-03256",
            How::Dynamic(SEMAPHORE_TYPE),
        )],
        ..NONE
    },
    Special {
        command: "vkSignalSemaphore",
        check: call("special::sync::signal_semaphore_checks", &["self", "signal_info"]),
        hold: call("special::sync::signal_semaphore_hold", &["self", "signal_info"]),
        after: call("special::sync::signal_semaphore_done", &["self", "signal_info"]),
        settles: &[
            ("VUID-VkSemaphoreSignalInfo-semaphore-03257", How::Dynamic(SEMAPHORE_TYPE)),
            ("VUID-VkSemaphoreSignalInfo-value-03258", How::Dynamic(HOST_SIGNAL)),
            ("VUID-VkSemaphoreSignalInfo-value-03259", How::Dynamic(HOST_SIGNAL)),
            ("VUID-VkSemaphoreSignalInfo-value-03260", How::User(UNPROVEN_HOST_DIFFERENCE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateEvent",
        created: call("special::sync::event_created", &["self", "created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkSetEvent",
        check: call(
            "special::sync::host_event",
            &["self", "event", "\"VUID-vkSetEvent-event-03941\""],
        ),
        hold: call("special::sync::set_event_hold", &["self"]),
        after: call("special::sync::host_event_set", &["self", "event"]),
        settles: &[("VUID-vkSetEvent-event-03941", How::Dynamic(DEVICE_ONLY))],
        ..NONE
    },
    Special {
        command: "vkResetEvent",
        check: call(
            "special::sync::host_event",
            &["self", "event", "\"VUID-vkResetEvent-event-03823\""],
        ),
        hold: call("special::sync::reset_event_hold", &["self", "event"]),
        after: call("special::sync::host_event_reset", &["self", "event"]),
        settles: &[
            ("VUID-vkResetEvent-event-03823", How::Dynamic(DEVICE_ONLY)),
            ("VUID-vkResetEvent-event-03821", How::Dynamic(HOST_RESET_PENDING)),
            ("VUID-vkResetEvent-event-03822", How::User(HOST_RESET_SAME)),
        ],
        ..NONE
    },
    Special {
        command: "vkGetEventStatus",
        check: call(
            "special::sync::host_event",
            &["self", "event", "\"VUID-vkGetEventStatus-event-03940\""],
        ),
        settles: &[("VUID-vkGetEventStatus-event-03940", How::Dynamic(DEVICE_ONLY))],
        ..NONE
    },
    Special {
        command: "vkCreateFence",
        check_last: call("special::sync::create_fence_checks", &["self", "create_info"]),
        settles: &[(
            "VUID-VkExportFenceCreateInfo-handleTypes-01446",
            How::Dynamic(EXPORTABLE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdWaitEvents",
        check: call(
            "special::sync::wait_events_checks",
            &[
                "self",
                "src_stage_mask",
                "dst_stage_mask",
                "memory_barriers",
                "buffer_memory_barriers",
                "image_memory_barriers",
            ],
        ),
        check_last: call(
            "special::sync::wait_events_signals",
            &["self", "events", "src_stage_mask"],
        ),
        after: call(
            "special::sync::wait_events_done",
            &["self", "events", "src_stage_mask", "dst_stage_mask", "image_memory_barriers"],
        ),
        settles: &[
            ("VUID-vkCmdWaitEvents-srcStageMask-01158", How::Dynamic(WAIT_SIGNALS)),
            ("VUID-vkCmdWaitEvents-pEvents-03847", How::Dynamic(WAIT_SIGNALS_ALONE)),
            ("VUID-vkCmdWaitEvents-srcAccessMask-02815", How::Dynamic(WAIT_SCOPES)),
            ("VUID-vkCmdWaitEvents-dstAccessMask-02816", How::Dynamic(WAIT_SCOPES)),
            ("VUID-vkCmdWaitEvents-pBufferMemoryBarriers-02817", How::Dynamic(WAIT_SCOPES)),
            ("VUID-vkCmdWaitEvents-pBufferMemoryBarriers-02818", How::Dynamic(WAIT_SCOPES)),
            ("VUID-vkCmdWaitEvents-pImageMemoryBarriers-02819", How::Dynamic(WAIT_SCOPES)),
            ("VUID-vkCmdWaitEvents-pImageMemoryBarriers-02820", How::Dynamic(WAIT_SCOPES)),
            ("VUID-vkCmdWaitEvents-srcStageMask-06459", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdWaitEvents-dstStageMask-06460", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdWaitEvents-srcStageMask-07308", How::Dynamic(WAIT_HOST_IN_PASS)),
            ("VUID-vkCmdWaitEvents-srcQueueFamilyIndex-02803", How::Dynamic(WAIT_FAMILIES)),
            ("VUID-vkCmdWaitEvents-srcStageMask-03937", How::Dynamic(EVENT_STAGES)),
            ("VUID-vkCmdWaitEvents-dstStageMask-03937", How::Dynamic(EVENT_STAGES)),
            ("VUID-vkCmdWaitEvents-commandBuffer-01167", How::User(UNPROVEN_ONE_DEVICE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdWaitEvents2",
        check: call(
            "special::sync::wait_events2_checks",
            &["self", "dependency_infos"],
        ),
        check_last: call(
            "special::sync::wait_events2_signals",
            &["self", "events", "dependency_infos"],
        ),
        after: call("special::sync::wait_events2_done", &["self", "events", "dependency_infos"]),
        settles: &[
            ("VUID-vkCmdWaitEvents2-pEvents-03837", How::Dynamic(WAIT_SIGNALS)),
            ("VUID-vkCmdWaitEvents2-pEvents-03838", How::Dynamic(WAIT_SIGNALS_ALONE)),
            ("VUID-vkCmdWaitEvents2-pEvents-03839", How::Dynamic(WAIT_SIGNALS)),
            ("VUID-vkCmdWaitEvents2-pEvents-03840", How::Dynamic(WAIT_HOST_BEFORE)),
            ("VUID-vkCmdWaitEvents2-pEvents-03841", How::Dynamic(WAIT_SIGNALS_ALONE)),
            ("VUID-vkCmdWaitEvents2-srcStageMask-03842", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdWaitEvents2-dstStageMask-03843", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdWaitEvents2-dependencyFlags-03844", How::Dynamic(WAIT_HOST_IN_PASS)),
            ("VUID-vkCmdWaitEvents2-commandBuffer-03846", How::User(UNPROVEN_ONE_DEVICE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetEvent",
        check_last: call("special::sync::set_event_checks", &["self", "stage_mask"]),
        after: call("special::sync::set_event_done", &["self", "event", "stage_mask"]),
        settles: &[
            ("VUID-vkCmdSetEvent-stageMask-06457", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdSetEvent-stageMask-03937", How::Dynamic(EVENT_STAGES)),
            ("VUID-vkCmdSetEvent-commandBuffer-01152", How::User(UNPROVEN_ONE_DEVICE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdResetEvent",
        check_last: call("special::sync::reset_event_checks", &["self", "event", "stage_mask"]),
        after: call("special::sync::reset_event_done", &["self", "event", "stage_mask"]),
        settles: &[
            ("VUID-vkCmdResetEvent-event-03834", How::Dynamic(RESET_RACE)),
            ("VUID-vkCmdResetEvent-event-03835", How::Dynamic(RESET_RACE)),
            ("VUID-vkCmdResetEvent-stageMask-06458", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdResetEvent-stageMask-03937", How::Dynamic(EVENT_STAGES)),
            ("VUID-vkCmdResetEvent-commandBuffer-01157", How::User(UNPROVEN_ONE_DEVICE)),
        ],
        ..NONE
    },
    // The current device mask, which the event commands read.
    Special {
        command: "vkCmdSetDeviceMask",
        check: call("special::sync::set_device_mask_checks", &["self", "device_mask"]),
        after: call("special::sync::device_mask_set", &["self", "device_mask"]),
        settles: &[
            ("VUID-vkCmdSetDeviceMask-deviceMask-00108", How::Dynamic(DEVICE_MASK)),
            ("VUID-vkCmdSetDeviceMask-deviceMask-00110", How::User(UNPROVEN_INITIAL_MASK)),
            ("VUID-vkCmdSetDeviceMask-deviceMask-00111", How::User(UNPROVEN_INITIAL_MASK)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetEvent2",
        check: call("special::sync::set_event2_checks", &["self", "dependency_info"]),
        after: call("special::sync::set_event2_done", &["self", "event", "dependency_info"]),
        settles: &[
            ("VUID-vkCmdSetEvent2-dependencyFlags-03825", How::Dynamic(SET_EVENT2_FLAGS)),
            ("VUID-vkCmdSetEvent2-srcStageMask-03827", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdSetEvent2-dstStageMask-03828", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdSetEvent2-commandBuffer-03826", How::User(UNPROVEN_ONE_DEVICE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdResetEvent2",
        check_last: call("special::sync::reset_event2_checks", &["self", "event", "stage_mask"]),
        after: call("special::sync::reset_event2_done", &["self", "event", "stage_mask"]),
        settles: &[
            ("VUID-vkCmdResetEvent2-event-03831", How::Dynamic(RESET_RACE)),
            ("VUID-vkCmdResetEvent2-event-03832", How::Dynamic(RESET_RACE)),
            ("VUID-vkCmdResetEvent2-commandBuffer-03833", How::User(UNPROVEN_ONE_DEVICE)),
        ],
        ..NONE
    },
    Special {
        command: "vkGetFenceStatus",
        after: call("special::sync::get_fence_status_done", &["fence", "r"]),
        ..NONE
    },
    Special {
        command: "vkWaitForFences",
        after: call("special::sync::wait_for_fences_done", &["self", "fences", "wait_all", "r"]),
        ..NONE
    },
    Special {
        command: "vkCreateSemaphore",
        check_last: call("special::sync::create_semaphore_checks", &["self", "create_info"]),
        created: call("special::sync::semaphore_created", &["self", "created", "create_info"]),
        settles: &[(
            "VUID-VkExportSemaphoreCreateInfo-handleTypes-01124",
            How::Dynamic(EXPORTABLE),
        )],
        ..NONE
    },
    Special {
        command: "vkDestroyFence",
        settles: &[(
            "VUID-vkDestroyFence-fence-01120",
            How::Static("a fence whose queue operation may still be executing waits for it before it is destroyed"),
        )],
        ..NONE
    },
    Special {
        command: "vkDestroySemaphore",
        settles: &[(
            "VUID-vkDestroySemaphore-semaphore-01137",
            How::Static("every queue operation holds the semaphores it names until it is known complete (its fence, a later fence of its queue, or an idle wait)"),
        )],
        ..NONE
    },
];
