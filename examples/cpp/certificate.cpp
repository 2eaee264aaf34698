// Every full-evidence answer carries a certificate that exact rational arithmetic alone can check,
// without any code of the classifier (doc/certificates.md).
#include <iostream>
#include <relpos/classify.hpp>

int main() {
  using namespace relpos;
  auto p = Paraboloid::standard({0, 0, 0}, Rational(1), Rational(2));
  auto e = Ellipsoid::sphere({0, 0, Rational(-1, 4)}, Rational(1, 4));  // touches the vertex from outside
  Classification c = classify(e, p);
  std::cout << to_string(c.verdict.position) << "\n";  // TE
  const Certificate& cert = c.certificate;
  std::cout << "lambda = " << to_string(cert.lambda) << ", contact point (" << to_string(cert.contact[0]) << ", "
            << to_string(cert.contact[1]) << ", " << to_string(cert.contact[2]) << ")\n";
  std::optional<std::string> problem = verify_certificate(e, p, c.verdict.position, cert);
  std::cout << (problem ? *problem : "certificate verified") << "\n";
  // The same evidence does not prove another position.
  problem = verify_certificate(e, p, Position::E, cert);
  std::cout << "as a proof of E: " << (problem ? *problem : "verified") << "\n";
}
// Output:
// TE
// lambda = 1/2, contact point (0, 0, 0)
// certificate verified
// as a proof of E: a certificate of kind tangent (lambda, contact) cannot prove position E
