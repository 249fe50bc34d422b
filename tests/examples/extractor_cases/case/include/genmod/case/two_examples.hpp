// Two examples; the indented block between them is prose.
//
// Example:
//   int a[] = {1, 2};   // [unbalanced ( ; semicolons
//     int b = a[1];
//
//   not code
//
// Example: the second one
//   int c = 3;
#pragma once
