% [s, which] = stable_solver(u, dy, phi): the closed form of (A.2) without
% cancellation (docs/equations.md, section 3): each case's root from the form
% whose terms have one sign. An example of a right solver for the adapter.
function [s, which] = stable_solver(u, dy, phi)
  if ~isfinite(u) || ~isfinite(dy) || ~isfinite(phi) || phi < 0
    s = NaN; which = 0; return;
  end
  if dy <= 0
    if u <= -dy
      s = -u; which = 1;
      return;
    end
    % impact, (A.11): every term has the sign of s (u > 0, dy <= 0)
    s = (2 * phi * dy - u - sqrt(u^2 - 4 * phi * dy * (u + dy))) / (2 * (1 + phi));
    which = 2;
    return;
  end
  if u >= dy * (phi - 1)
    % contact, (A.19): 2 phi dy - u cancels where u is near 2 phi dy, so
    % 2 phi dy is carried as an exact sum of two doubles (Dekker's product)
    [high, low] = exact_product(2 * phi, dy);
    s = ((high - u) + low) / (1 + phi); which = 3;
  else
    % release: s = (-u + sqrt(u^2 + 4 phi dy^2)) / 2, rationalised
    t = u^2 + 4 * phi * dy^2;
    if u >= 0
      s = 2 * phi * dy^2 / (u + sqrt(t));
    else
      s = (-u + sqrt(t)) / 2;
    end
    which = 4;
  end
end

% a * b = high + low exactly (Veltkamp's split; no fma in Octave)
function [high, low] = exact_product(a, b)
  high = a * b;
  [a1, a2] = split(a);
  [b1, b2] = split(b);
  low = ((a1 * b1 - high) + a1 * b2 + a2 * b1) + a2 * b2;
end

function [upper, lower] = split(x)
  c = 134217729 * x;  % 2^27 + 1
  upper = c - (c - x);
  lower = x - upper;
end
