// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file main.cxx
 * labelmesher-gui [LABEL_IMAGE]: the desktop viewer (MainWindow.h). Errors are
 * shown in a message box, one sentence each.
 */

#include "MainWindow.h"
#include "MpiSession.h"

#include "QVTKOpenGLNativeWidget.h"

#include "itkObject.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QSurfaceFormat>

int main(int argc, char* argv[])
{
  const labelmesher::gui::MpiSession mpi; // before any worker thread meshes
  // VTK's OpenGL needs its surface format set before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setApplicationName("labelmesher-gui");
  QApplication::setApplicationVersion(LABELMESHER_VERSION);
  // VTK's output window stays: the filters' errors and warnings are caught by the run
  // (FilterRun.h); what else VTK reports (an OpenGL failure) goes to stderr.
  itk::Object::GlobalWarningDisplayOff(); // ITK's warnings; its errors arrive as exceptions

  QCommandLineParser parser;
  parser.setApplicationDescription("LabelMesher: guaranteed-quality meshes from label images");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("image", "label image to open (NRRD, NHDR, NIfTI, MetaImage, VTI, PNG, .seg.nrrd)");
  parser.process(app);

  labelmesher::gui::MainWindow window;
  QObject::connect(&window, &labelmesher::gui::MainWindow::errorOccurred, &window,
    [&window](const QString& message) { QMessageBox::warning(&window, "LabelMesher", message); });
  window.show();
  if (!parser.positionalArguments().isEmpty())
  {
    window.openImage(parser.positionalArguments().first());
  }
  return app.exec();
}
