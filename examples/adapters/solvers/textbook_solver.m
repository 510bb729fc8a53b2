% [s, which] = textbook_solver(u, dy, phi): stable_solver.m with one fault
% planted: the release root as printed, (A.25), which cancels where
% u >> sqrt(phi) dy. An example of a wrong solver for the adapter (which adds
% this folder, and so stable_solver.m, to the path).
function [s, which] = textbook_solver(u, dy, phi)
  [s, which] = stable_solver(u, dy, phi);
  if which == 4
    s = -u / 2 + sqrt(u^2 + 4 * phi * dy^2) / 2;
  end
end
