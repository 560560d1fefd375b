"""Reading sluice's OUT/probes.csv: time and one probe's column, chosen by name."""
import csv

from runs import open_text


def read_probe(path, name):
    """Returns (times, values) of the column whose header starts with the probe's name (path:
    a probes.csv, or its gzipped copy)."""
    times, values = [], []
    with open_text(path) as f:
        reader = csv.reader(f)
        header = next(reader)
        column = next(i for i, title in enumerate(header) if title.startswith(name + " "))
        for row in reader:
            times.append(float(row[0]))
            values.append(float(row[column]))
    return times, values
