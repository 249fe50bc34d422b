// A header whose example marker has no code.
//
// Example:
//
//   (this is after the blank line, so not part of it)
#pragma once
