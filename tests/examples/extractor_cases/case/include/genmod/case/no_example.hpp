// A header with an indented block but no marker.
//
//   int x = 1;
#pragma once
