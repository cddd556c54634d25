// SPDX-License-Identifier: GPL-2.0-or-later
#include "AngleHistogram.h"

#include "vtkIdList.h"
#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <QPaintEvent>
#include <QPainter>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace labelmesher
{
namespace widgets
{
namespace
{
const int kBins = static_cast<int>(AngleHistogram::LargestAngle / AngleHistogram::BinWidth);

using Vector = std::array<double, 3>;

Vector Minus(const Vector& a, const Vector& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The angle between u and v in degrees; atan2 keeps small angles accurate.
double AngleBetween(const Vector& u, const Vector& v)
{
  const Vector w = Cross(u, v);
  return std::atan2(std::sqrt(Dot(w, w)), Dot(u, v)) * 180.0 / M_PI;
}

double SmallestTriangleAngle(const std::array<Vector, 4>& p)
{
  double smallest = 180.0;
  for (int i = 0; i < 3; ++i)
  {
    const Vector& a = p[static_cast<std::size_t>(i)];
    smallest = std::min(smallest,
      AngleBetween(Minus(p[static_cast<std::size_t>((i + 1) % 3)], a), Minus(p[static_cast<std::size_t>((i + 2) % 3)], a)));
  }
  return smallest;
}

/// The smallest of the six dihedral angles: at edge (a, b), the angle between the normals of
/// (a, b, c) and (a, b, d) both taken as e x (c - a), e x (d - a) with e = b - a.
double SmallestDihedralAngle(const std::array<Vector, 4>& p)
{
  constexpr int kEdges[6][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 3, 1, 2 }, { 1, 2, 0, 3 }, { 1, 3, 0, 2 },
    { 2, 3, 0, 1 } };
  double smallest = 180.0;
  for (const auto& e : kEdges)
  {
    const Vector& a = p[e[0]];
    const Vector edge = Minus(p[e[1]], a);
    smallest = std::min(smallest, AngleBetween(Cross(edge, Minus(p[e[2]], a)), Cross(edge, Minus(p[e[3]], a))));
  }
  return smallest;
}
} // namespace

AngleHistogram::AngleHistogram(QWidget* parent)
  : QWidget(parent)
  , Counts(kBins, 0)
{
  this->setObjectName("angleHistogram");
  this->setToolTip(tr("Cells by their smallest angle (triangles: interior angle; tetrahedra: dihedral "
                      "angle), measured from the points. The red line is the angle bound."));
  this->setMinimumHeight(120);
}

void AngleHistogram::clear()
{
  std::fill(this->Counts.begin(), this->Counts.end(), 0);
  this->Cells = 0;
  this->Smallest = 0.0;
  this->Bound = 0.0;
  this->update();
}

void AngleHistogram::setMesh(vtkUnstructuredGrid* mesh, double bound)
{
  this->clear();
  this->Bound = bound;
  if (!mesh)
  {
    return;
  }
  double smallest = std::numeric_limits<double>::infinity();
  vtkNew<vtkIdList> ids;
  std::array<Vector, 4> p;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const int type = mesh->GetCellType(c);
    if (type != VTK_TRIANGLE && type != VTK_TETRA)
    {
      continue;
    }
    mesh->GetCellPoints(c, ids);
    for (vtkIdType v = 0; v < ids->GetNumberOfIds(); ++v)
    {
      mesh->GetPoint(ids->GetId(v), p[static_cast<std::size_t>(v)].data());
    }
    const double angle = type == VTK_TRIANGLE ? SmallestTriangleAngle(p) : SmallestDihedralAngle(p);
    const int bin = std::clamp(static_cast<int>(std::floor(angle / BinWidth)), 0, kBins - 1);
    ++this->Counts[static_cast<std::size_t>(bin)];
    ++this->Cells;
    smallest = std::min(smallest, angle);
  }
  this->Smallest = this->Cells > 0 ? smallest : 0.0;
  this->update();
}

void AngleHistogram::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(this->rect(), this->palette().base());
  const QFontMetrics metrics = painter.fontMetrics();
  const int textHeight = metrics.height();
  const QRect plot = this->rect().adjusted(8, textHeight + 6, -8, -(textHeight + 6));
  if (plot.width() < kBins || plot.height() < 10)
  {
    return;
  }
  const vtkIdType tallest = std::max<vtkIdType>(1, *std::max_element(this->Counts.begin(), this->Counts.end()));
  const double barWidth = static_cast<double>(plot.width()) / kBins;
  painter.setPen(Qt::NoPen);
  painter.setBrush(QColor(68, 119, 170));
  for (int i = 0; i < kBins; ++i)
  {
    const vtkIdType count = this->Counts[static_cast<std::size_t>(i)];
    if (count == 0)
    {
      continue;
    }
    // Square-root scale: a lone cell near the bound stays visible beside thousands elsewhere.
    const double height = std::sqrt(static_cast<double>(count) / static_cast<double>(tallest)) * plot.height();
    painter.drawRect(QRectF(plot.left() + i * barWidth, plot.bottom() - height, std::max(1.0, barWidth - 1), height));
  }
  painter.setPen(this->palette().text().color());
  painter.drawLine(plot.bottomLeft(), plot.bottomRight());
  for (int degrees = 0; degrees <= static_cast<int>(LargestAngle); degrees += 15)
  {
    const double x = plot.left() + degrees / LargestAngle * plot.width();
    painter.drawLine(QPointF(x, plot.bottom()), QPointF(x, plot.bottom() + 3));
    painter.drawText(QRectF(x - 20, plot.bottom() + 4, 40, textHeight), Qt::AlignHCenter,
      QString::number(degrees) + QChar(0x00B0));
  }
  if (this->Bound > 0.0)
  {
    const double x = plot.left() + std::min(this->Bound, LargestAngle) / LargestAngle * plot.width();
    painter.setPen(QPen(QColor(204, 51, 17), 2));
    painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
  }
  painter.setPen(this->palette().text().color());
  const QString title = this->Cells == 0
    ? tr("smallest angle per cell: no mesh")
    : tr("smallest angle per cell: %1 cells, smallest %2%3, bound %4%3 (square-root scale)")
        .arg(this->Cells)
        .arg(this->Smallest, 0, 'f', 2)
        .arg(QChar(0x00B0))
        .arg(this->Bound, 0, 'f', 1);
  painter.drawText(QRect(8, 2, this->width() - 16, textHeight), Qt::AlignLeft, title);
}

} // namespace widgets
} // namespace labelmesher
