// fields.cpp - field names, parsing and sets.
#include "ggxcl/fields.hpp"

#include "ggxcl/error.hpp"

namespace ggxcl {

std::string_view field_name(Field field)
{
    switch (field) {
    case Field::m: return "m";
    case Field::o: return "o";
    case Field::pdf_m: return "pdf_m";
    case Field::pdf_o: return "pdf_o";
    case Field::weight: return "weight";
    case Field::u: return "u";
    }
    return "unknown";
}

Field parse_field(std::string_view name)
{
    for (Field field : all_fields)
        if (field_name(field) == name)
            return field;
    throw InvalidArgument("field", std::string(name), "one of " + field_list());
}

int field_columns(Field field)
{
    if (field == Field::m || field == Field::o)
        return 3;
    return field == Field::u ? 2 : 1;
}

int field_columns(Field field, bool dielectric)
{
    return field == Field::u && dielectric ? 3 : field_columns(field);
}

std::string field_list()
{
    std::string list;
    for (Field field : all_fields)
        list += (list.empty() ? "" : ", ") + std::string(field_name(field));
    return list;
}

std::vector<Field> parse_field_list(std::string_view list)
{
    std::vector<Field> fields;
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t comma = list.find(',', start);
        std::size_t end = comma == std::string_view::npos ? list.size() : comma;
        Field field = parse_field(list.substr(start, end - start));
        for (Field seen : fields)
            if (seen == field)
                throw InvalidArgument("fields", std::string(list), "each field at most once");
        fields.push_back(field);
        start = end + 1;
    }
    return fields;
}

FieldSet::FieldSet(std::initializer_list<Field> fields)
{
    for (Field field : fields)
        add(field);
}

FieldSet::FieldSet(const std::vector<Field>& fields)
{
    for (Field field : fields)
        add(field);
}

FieldSet FieldSet::all()
{
    return FieldSet({all_fields.begin(), all_fields.end()});
}

} // namespace ggxcl
