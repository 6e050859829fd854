#pragma once
/// @file
/// @brief The engine's threads yield the processor to the window's.

namespace cam {

/// @brief Lowers the scheduling priority of the calling thread: called first thing by every
/// thread that computes for the window (the engine's worker, its pool tasks, synthesis,
/// exports). On a machine with as many busy compute threads as cores, the window's thread
/// otherwise waits for a core each time it wakes (input, a timer, a result to draw): stalls of
/// 9 to 13 ms while edits streamed in on this project's 2-core machine. Linux: nice +10 for
/// this thread alone (QThread priorities do nothing under the default scheduling policy).
/// Only ever lowers; calling it again changes nothing.
void runInTheBackground();

}  // namespace cam
