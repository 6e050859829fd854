#pragma once
/// @file
/// @brief How the process keeps the memory of one computation for the next.

namespace cam {

/// @brief Keeps freed memory in the process for the next edit's results instead of giving it
/// back to the system at once. Every edit allocates its result afresh (plot levels, plot
/// containers: a few MB at 100,000 samples, tens of MB at a million) and frees the previous
/// one; by default glibc maps blocks above 128 kB afresh and unmaps them when freed, and trims
/// the heap's free top, so each edit touched thousands of new pages, each a page fault: about
/// 7,600 per edit at 100,000 samples (first picture and refinement), a fifth of the first
/// picture's time and half of the whole computation's on this project's machine. Blocks up to
/// 32 MB now come from the heap, and up to 128 MB of free heap stay. Call once, first thing in
/// main(). Does nothing where the C library is not glibc.
void keepFreedMemoryForReuse();

}  // namespace cam
