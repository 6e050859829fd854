#include "widgets/icons.h"

namespace cam {

QIcon actionIcon(const QString& name) {
    const QIcon ours(QStringLiteral(":/icons/actions/%1.svg").arg(name));
    if (name.startsWith(QLatin1String("camwright-"))) return ours;
    return QIcon::fromTheme(name, ours);
}

}  // namespace cam
