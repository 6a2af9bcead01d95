"""dtoadq preview sheet: preview renders side by side, each titled with its material.
Reads the list written by plots/preview_sheet.cpp (title,path)."""
import math

import matplotlib.image as mpimg

import plot_common
from plot_common import plt


def main():
    parser = plot_common.argument_parser()
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    rows = list(plot_common.read_rows(args.data))
    columns = min(5, len(rows))
    lines = math.ceil(len(rows) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(3.2 * columns, 3.4 * lines + 0.4), squeeze=False)
    for axis in axes.flat:
        axis.axis("off")
    for axis, row in zip(axes.flat, rows):
        axis.imshow(mpimg.imread(row["path"]))
        axis.set_title(row["title"], fontsize=10)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    plot_common.save(fig, args.out, 100)


if __name__ == "__main__":
    main()
