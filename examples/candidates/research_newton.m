% [s, which] = research_newton(u, dy, phi): Newton's method on the residual
% of (A.2) in the manner of published research code for energy-stable
% string-barrier collisions (see README.md here): start at s0 = 100 eps,
% stop when the step is below eps (an absolute tolerance), at most 100
% iterations, and the divided difference regularised by eps^2 so that it
% never divides by zero. Written for this project from that description.
%
%   contact-check --candidate "cmd:octave-cli examples/adapters/check_octave.m examples/candidates/research_newton.m"
function [s, which] = research_newton(u, dy, phi)
  if ~isfinite(u) || ~isfinite(dy) || ~isfinite(phi) || phi < 0
    s = NaN; which = 0; return;
  end
  s = 100 * eps;
  for iteration = 1:100
    p = max(dy - s, 0); p0 = max(dy, 0);
    change = p^2 - p0^2;
    denominator = s^2 + eps^2;
    r = s + u + phi * change * s / denominator;
    slope = 1 + phi * ((change - 2 * p * s) * denominator - 2 * change * s^2) / denominator^2;
    step = r / slope;
    s = s - step;
    if abs(step) < eps
      break;
    end
  end
  if dy <= 0
    which = 1 + (s < dy);
  else
    which = 3 + (s > dy);
  end
end
